// `sanet report`: a metric of a study's runs against a varied parameter, as mean and 95 %
// confidence interval per value (one series per combination of the other parameters), printed,
// plotted (SVG or PNG, PLplot) and exported as CSV.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/statistics.h"

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
  // Every scalar name, with how many runs have it.
  std::vector<std::pair<std::string, int>> Metrics() const;
  // run id -> value, for the completed runs that have it. Unknown names: ReportError with the closest.
  std::map<long, double> Values(const std::string& metric) const;
  // A varied parameter by its path or its short name ("NodeTraversalTime"); "" stays "".
  std::string Parameter(const std::string& name) const;
  // When the completed runs met the scenario's end condition (not its duration).
  std::vector<double> EndConditionTimes() const;

 private:
  sqlite3* db_ = nullptr;
  std::vector<std::string> parameters_;
  std::vector<StudyRun> runs_;
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

std::string FormatTable(const std::string& metric, const std::string& by, const std::vector<Series>& series);
// Per run: name, seed, status, parameters, then each metric. Written whole.
void WriteCsv(const StudyReader& study, const std::vector<std::string>& metrics, const std::string& path);
// A plot's file name must end in .svg or .png (ReportError otherwise).
void CheckPlotName(const std::string& path);
// Mean with its interval against the parameter, a line per series; .svg or .png by the name.
void Plot(const std::string& metric, const std::string& by, const std::vector<Series>& series, const std::string& path);

}  // namespace sanet::study
