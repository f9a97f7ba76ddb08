// `sanet report`: a metric of a study's runs against a varied parameter, as mean and 95 %
// confidence interval per value (one series per combination of the other parameters), printed,
// plotted (SVG or PNG, PLplot) and exported as CSV. A metric is a number of the runs'
// summary.json, an expression over them (study/metric_expression.h) or a derived metric
// defined by name; per-node metrics are listed folded over the nodes (study/node_fold.h).
#pragma once

#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/statistics.h"
#include "study/metric_expression.h"

struct sqlite3;

namespace sanet::study {

class ReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct StudyRun {
  long id = 0;
  std::string name, status;
  std::uint64_t seed = 0;
  std::map<std::string, std::string> values;  // parameter -> value
};

// A study database opened for reading.
class StudyReader {
 public:
  // `where`: the study's folder or its study.sqlite.
  explicit StudyReader(const std::string& where);
  ~StudyReader();
  StudyReader(const StudyReader&) = delete;
  StudyReader& operator=(const StudyReader&) = delete;

  const std::vector<std::string>& parameters() const { return parameters_; }
  const std::vector<StudyRun>& runs() const { return runs_; }
  struct MetricInfo {
    std::string name;  // a scalar's name, or a folded one's default expression
    int runs = 0;      // completed runs that have it
    int nodes = 0;     // folded: the most nodes one run has it for; 0 for a run-wide metric
  };
  // Every metric, per-node ones folded by name unless `per_node`.
  std::vector<MetricInfo> Metrics(bool per_node = false) const;
  // `--derive NAME=EXPR`: a metric of each run computed from its others. ReportError when the
  // name is taken or the expression is malformed or reads what no run has.
  void Define(const std::string& name, const std::string& expression);
  // run id -> value of a metric, a derived metric or an expression, for the completed runs that
  // have one. Unknown names: ReportError with the closest.
  std::map<long, double> Values(const std::string& metric) const;
  // The --derive definitions, in the order given: (name, expression).
  const std::vector<std::pair<std::string, std::string>>& definitions() const { return definitions_; }
  int CompletedRuns() const;
  // A varied parameter by its path or its short name ("NodeTraversalTime"); "" stays "".
  std::string Parameter(const std::string& name) const;
  // When the completed runs met the scenario's end condition (not its duration).
  std::vector<double> EndConditionTimes() const;

 private:
  const std::map<long, RunMetrics>& Completed() const;  // read once, when first asked
  std::set<std::string> NodesOf(long run) const;
  std::optional<double> Derive(const std::string& name, const RunMetrics& run) const;
  void CheckReads(const MetricExpression& e) const;
  [[noreturn]] void Unknown(const std::string& what, const std::string& name) const;

  sqlite3* db_ = nullptr;
  std::string folder_;
  std::vector<std::string> parameters_;
  std::vector<StudyRun> runs_;
  std::map<std::string, MetricExpression> derived_;
  std::vector<std::pair<std::string, std::string>> definitions_;
  mutable std::optional<std::map<long, RunMetrics>> completed_;
  mutable std::map<long, std::set<std::string>> nodes_;
  bool has_nodes_table_ = false;  // studies begun before sanet kept one have none
};

struct Point {
  std::string x;  // the parameter's value
  MeanCi stats;
  double median = 0;
};

struct Series {
  std::string label;  // the other parameters' values ("" when there are none)
  std::vector<Point> points;
};

// The metric grouped by the values of `by` ("" : all runs in one group), a series per
// combination of the other parameters. Points follow the values' order (numerically when all
// are numbers).
std::vector<Series> Summarise(const StudyReader& study, const std::string& metric, const std::string& by);

// "" or a warning that some groups have too few runs for their intervals to mean much.
std::string FewRunsWarning(const std::vector<Series>& series);
std::string FormatTable(const std::string& metric, const std::string& by, const std::vector<Series>& series);
// Per run: id, name, seed, status, parameters, then each metric. Written whole.
void WriteCsv(const StudyReader& study, const std::vector<std::string>& metrics, const std::string& path);
// A plot's file name must end in .svg or .png (ReportError otherwise).
void CheckPlotName(const std::string& path);
struct PlotText {
  std::string title, xlabel, ylabel;  // "": sanet's (the parameter's last path part, the metric)
};
// One metric's series, named.
struct MetricSeries {
  std::string metric;
  std::vector<Series> series;
};
// Mean with its interval against the parameter, a line per metric and series, in one plot;
// .svg or .png by the name.
void Plot(const std::vector<MetricSeries>& metrics, const std::string& by, const PlotText& text,
          const std::string& path);

}  // namespace sanet::study
