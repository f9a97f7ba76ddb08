#include "study/report.h"

#include <sqlite3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "core/closest_names.h"
#include "study/grid.h"
#include "study/node_fold.h"
#include "study/study_db.h"
#include "trace/csv_sink.h"

namespace sanet::study {
namespace {

namespace fs = std::filesystem;

// Rows of a query, as text.
std::vector<std::vector<std::string>> Query(sqlite3* db, const std::string& sql) {
  sqlite3_stmt* stmt = nullptr;
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt, nullptr) != SQLITE_OK)
    throw ReportError(std::string("study database: ") + sqlite3_errmsg(db));
  std::vector<std::vector<std::string>> rows;
  while (sqlite3_step(stmt) == SQLITE_ROW) {
    rows.emplace_back();
    for (int c = 0; c < sqlite3_column_count(stmt); ++c) {
      const unsigned char* t = sqlite3_column_text(stmt, c);
      rows.back().push_back(t ? reinterpret_cast<const char*>(t) : "");
    }
  }
  sqlite3_finalize(stmt);
  return rows;
}

// The values of `by` in order: numerically when every one is a number, else as first seen.
std::vector<std::string> Ordered(std::vector<std::string> values) {
  const bool numbers =
      std::all_of(values.begin(), values.end(), [](const std::string& v) { return NumberIn(v).has_value(); });
  std::vector<std::string> unique;
  for (const std::string& v : values)
    if (std::find(unique.begin(), unique.end(), v) == unique.end()) unique.push_back(v);
  if (numbers)
    std::sort(unique.begin(), unique.end(), [](const auto& a, const auto& b) { return std::stod(a) < std::stod(b); });
  return unique;
}

std::string Label(const StudyRun& run, const std::vector<std::string>& parameters, const std::string& by) {
  std::string label;
  for (const std::string& p : parameters)
    if (p != by) label += (label.empty() ? "" : ", ") + p + "=" + run.values.at(p);
  return label;
}

std::string Format(double v, int digits = 6) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

}  // namespace

StudyReader::StudyReader(const std::string& where) {
  const std::string path = fs::is_directory(where) ? (fs::path(where) / "study.sqlite").string() : where;
  folder_ = fs::path(path).parent_path().string();
  if (!fs::exists(path)) throw ReportError(where + " is not a study: no " + path + " (sanet sweep makes one)");
  if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    sqlite3_close(db_);
    throw ReportError("cannot open " + path);
  }
  sqlite3_busy_timeout(db_, 10000);  // the sweep may be writing
  try {
    for (const auto& row : Query(db_, "SELECT value FROM study WHERE key = 'parameters'")) {
      std::stringstream lines(row[0]);
      for (std::string p; std::getline(lines, p);) parameters_.push_back(p);
    }
    for (const auto& row : Query(db_, "SELECT id, name, seed, status FROM runs ORDER BY id"))
      runs_.push_back({std::stol(row[0]), row[1], row[3], std::stoull(row[2]), {}});
    std::map<long, StudyRun*> by_id;
    for (StudyRun& r : runs_) by_id[r.id] = &r;
    has_nodes_table_ = !Query(db_, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'nodes'").empty();
    for (const auto& row : Query(db_, "SELECT run, name, value FROM parameters"))
      by_id.at(std::stol(row[0]))->values[row[1]] = row[2];
  } catch (const std::exception& e) {
    sqlite3_close(db_);
    throw ReportError(path + " is not a study database sanet can read (" + e.what() + ")");
  }
}

StudyReader::~StudyReader() { sqlite3_close(db_); }

const std::map<long, RunMetrics>& StudyReader::Completed() const {
  if (completed_) return *completed_;
  completed_.emplace();
  for (const StudyRun& r : runs_)
    if (r.status == "completed") (*completed_)[r.id];
  for (const auto& row : Query(db_,
                               "SELECT s.run, s.name, s.value FROM scalars s JOIN runs r ON r.id = s.run "
                               "WHERE r.status = 'completed'"))
    if (!row[2].empty()) (*completed_)[std::stol(row[0])][row[1]] = std::stod(row[2]);
  return *completed_;
}

int StudyReader::CompletedRuns() const { return static_cast<int>(Completed().size()); }

// From the study's nodes table; for a study begun before sanet kept one, from the run's
// summary.json.
std::set<std::string> StudyReader::NodesOf(long run) const {
  if (auto it = nodes_.find(run); it != nodes_.end()) return it->second;
  std::set<std::string>& names = nodes_[run];
  if (has_nodes_table_)
    for (const auto& row : Query(db_, "SELECT name FROM nodes WHERE run = " + std::to_string(run)))
      names.insert(row[0]);
  if (!names.empty()) return names;
  for (const auto& row : Query(db_, "SELECT folder FROM runs WHERE id = " + std::to_string(run))) {
    std::ifstream in(fs::path(folder_) / row[0] / "summary.json");
    for (const std::string& name : NodeNames(nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false)))
      names.insert(name);
  }
  return names;
}

// A metric that more than one node of some run has is listed folded; one only ever a single
// node has (the one robot's) keeps its own name. The list is in the order of the names inside.
std::vector<StudyReader::MetricInfo> StudyReader::Metrics(bool per_node) const {
  struct Family {
    std::set<long> runs;
    int nodes = 0;
    std::map<std::string, int> names;  // -> runs that have it
  };
  std::map<std::string, Family> families;  // by pattern, or by name for run-wide metrics
  for (const auto& [id, run] : Completed()) {
    const std::set<std::string> nodes = per_node ? std::set<std::string>{} : NodesOf(id);
    std::map<std::string, int> in_run;
    for (const auto& [name, value] : run) {
      const std::string pattern = NodePattern(name, nodes);
      Family& f = families[pattern.empty() ? name : pattern];
      f.runs.insert(id), ++f.names[name], ++in_run[pattern];
    }
    for (const auto& [pattern, count] : in_run)
      if (!pattern.empty()) families[pattern].nodes = std::max(families[pattern].nodes, count);
  }
  std::vector<MetricInfo> list;
  for (const auto& [key, f] : families) {
    if (f.nodes > 1) {
      list.push_back({FoldedExpression(key), static_cast<int>(f.runs.size()), f.nodes});
      continue;
    }
    for (const auto& [name, runs] : f.names) list.push_back({name, runs, 0});
  }
  return list;
}

void StudyReader::Define(const std::string& name, const std::string& expression) {
  if (!IsPlainName(name) || name.find('*') != std::string::npos)
    throw ReportError("--derive: '" + name + "' is not a name (a letter or '_', then letters, digits, '_' and '.')");
  if (derived_.count(name)) throw ReportError("--derive: '" + name + "' is derived twice");
  for (const auto& [id, run] : Completed())
    if (run.count(name)) throw ReportError("--derive: '" + name + "' is already a metric of the runs");
  try {
    MetricExpression e = MetricExpression::Parse(expression);
    CheckReads(e);
    derived_.emplace(name, std::move(e));
    definitions_.emplace_back(name, expression);
  } catch (const ExpressionError& e) {
    throw ReportError("--derive " + name + ": " + e.what());
  }
}

std::optional<double> StudyReader::Derive(const std::string& name, const RunMetrics& run) const {
  auto it = derived_.find(name);
  if (it == derived_.end()) return std::nullopt;
  return it->second.Evaluate(run, [this](const std::string& n, const RunMetrics& r) { return Derive(n, r); });
}

// Every name the expression reads is a metric of some run or an earlier derived one, and every
// pattern matches something: a typo is an error, not a column of nothing.
void StudyReader::CheckReads(const MetricExpression& e) const {
  const auto& completed = Completed();
  if (completed.empty()) throw ReportError("no run of this study has completed yet");
  for (const std::string& name : e.names()) {
    const bool known = derived_.count(name) || std::any_of(completed.begin(), completed.end(),
                                                           [&](const auto& r) { return r.second.count(name) > 0; });
    if (!known) Unknown("metric", name);
  }
  for (const std::string& pattern : e.patterns()) {
    const bool matched = std::any_of(completed.begin(), completed.end(), [&](const auto& r) {
      return std::any_of(r.second.begin(), r.second.end(),
                         [&](const auto& m) { return MatchesPattern(pattern, m.first); });
    });
    if (!matched) Unknown("metric matching", pattern);
  }
}

// A name is compared with every metric's and derived name; a pattern with the folded ones.
void StudyReader::Unknown(const std::string& what, const std::string& name) const {
  const bool pattern = name.find('*') != std::string::npos;
  std::vector<std::string> names;
  for (const MetricInfo& m : Metrics(/*per_node=*/!pattern)) {
    if (!pattern) names.push_back(m.name);
    if (pattern && m.nodes > 0)
      names.push_back(m.name.substr(m.name.find('(') + 1, m.name.size() - m.name.find('(') - 2));
  }
  for (const auto& [derived, e] : derived_) names.push_back(derived);
  std::vector<std::string> close = ClosestNames(name, names);
  for (const std::string& n : names)  // a part of a name: "delay" for message_delay_s.median
    if (close.size() < 3 && n.find(name) != std::string::npos &&
        std::find(close.begin(), close.end(), n) == close.end())
      close.push_back(n);
  const std::string order = derived_.empty() || pattern ? "" : " (a --derive name is known only after its definition)";
  throw ReportError("no completed run has a " + what + " '" + name + "'" +
                    (close.empty() ? "" : " (did you mean " + OrList(close) + "?)") + order +
                    "; sanet report --list lists them");
}

// A derived name, then a metric's exact name (whatever characters it holds), then an expression.
std::map<long, double> StudyReader::Values(const std::string& metric) const {
  std::map<long, double> values;
  if (!derived_.count(metric)) {
    for (const auto& [id, run] : Completed())
      if (auto it = run.find(metric); it != run.end()) values[id] = it->second;
    if (!values.empty()) return values;
  }
  std::optional<MetricExpression> parsed;
  const MetricExpression* e = nullptr;
  if (auto it = derived_.find(metric); it != derived_.end()) {
    e = &it->second;
  } else {
    try {
      parsed = MetricExpression::Parse(metric);
    } catch (const ExpressionError& error) {
      throw ReportError(std::string("-m: ") + error.what());
    }
    CheckReads(*parsed);
    e = &*parsed;
  }
  const auto derive = [this](const std::string& n, const RunMetrics& r) { return Derive(n, r); };
  for (const auto& [id, run] : Completed())
    if (const std::optional<double> v = e->Evaluate(run, derive)) values[id] = *v;
  return values;
}

std::vector<double> StudyReader::EndConditionTimes() const {
  std::vector<double> times;
  for (const auto& row : Query(db_,
                               "SELECT ended_at_s FROM runs WHERE status = 'completed' AND ended_by != "
                               "'duration' ORDER BY id"))
    times.push_back(std::stod(row[0]));
  return times;
}

std::string StudyReader::Parameter(const std::string& name) const {
  const auto& ps = parameters_;
  if (name.empty() || std::find(ps.begin(), ps.end(), name) != ps.end()) return name;
  std::vector<std::string> matches;
  for (const std::string& p : ps)
    if (ShortName(p) == name) matches.push_back(p);
  if (matches.size() == 1) return matches.front();
  std::string varied;
  for (const std::string& p : ps) varied += (varied.empty() ? "" : ", ") + p;
  throw ReportError("the study does not vary '" + name + "'" +
                    (ps.empty() ? " (it varies only the seed)" : " (it varies " + varied + ")"));
}

std::vector<Series> Summarise(const StudyReader& study, const std::string& metric, const std::string& by_name) {
  const auto& ps = study.parameters();
  const std::string by = study.Parameter(by_name);
  const std::map<long, double> values = study.Values(metric);
  std::vector<std::string> xs, labels;
  for (const StudyRun& r : study.runs()) {
    xs.push_back(by.empty() ? "all" : r.values.at(by));
    labels.push_back(Label(r, ps, by));
  }
  std::vector<Series> series;
  for (const std::string& label : Ordered(labels)) {
    Series s{label, {}};
    for (const std::string& x : Ordered(xs)) {
      std::vector<double> samples;
      for (std::size_t i = 0; i < study.runs().size(); ++i)
        if (xs[i] == x && labels[i] == label && values.count(study.runs()[i].id))
          samples.push_back(values.at(study.runs()[i].id));
      if (!samples.empty()) s.points.push_back({x, MeanWithCi(samples), Quantile(samples, 0.5)});
    }
    series.push_back(s);
  }
  return series;
}

// Below this many runs a group's 95 % interval is too wide, and too dependent on the runs being
// near normal, to mean much.
constexpr int kFewRuns = 5;

std::string FewRunsWarning(const std::vector<Series>& series) {
  int few = 0, groups = 0, fewest = 1 << 30;
  for (const Series& s : series)
    for (const Point& p : s.points) {
      ++groups;
      if (p.stats.count < kFewRuns) ++few, fewest = std::min(fewest, p.stats.count);
    }
  if (few == 0) return "";
  return "warning: " + std::to_string(few) + " of " + std::to_string(groups) + " groups " +
         (few == 1 ? "has" : "have") + " fewer than " + std::to_string(kFewRuns) +
         " runs (the fewest: " + std::to_string(fewest) +
         "); an interval from so few runs means little (wide, or narrow only by chance, and leaning on " +
         "the values being near normal): give the sweep more seeds (--seeds 1-10)\n";
}

std::string FormatTable(const std::string& metric, const std::string& by, const std::vector<Series>& series) {
  std::ostringstream out;
  char line[256];
  for (const Series& s : series) {
    out << metric << (by.empty() ? "" : " by " + by) << (s.label.empty() ? "" : " (" + s.label + ")") << ":\n";
    std::snprintf(line, sizeof line, "  %-14s %5s %12s %12s %25s\n", by.empty() ? "" : "value", "runs", "mean",
                  "median", "95% confidence interval");
    out << line;
    for (const Point& p : s.points) {
      const std::string interval = p.stats.count > 1 ? "[" + Format(p.stats.mean - p.stats.half_width) + ", " +
                                                           Format(p.stats.mean + p.stats.half_width) + "]"
                                                     : "(one run)";
      std::snprintf(line, sizeof line, "  %-14s %5d %12s %12s %25s\n", p.x.c_str(), p.stats.count,
                    Format(p.stats.mean).c_str(), Format(p.median).c_str(), interval.c_str());
      out << line;
    }
  }
  return out.str();
}

void WriteCsv(const StudyReader& study, const std::vector<std::string>& metrics, const std::string& path) {
  std::vector<std::map<long, double>> columns;
  for (const std::string& m : metrics) columns.push_back(study.Values(m));
  std::string csv = "run_id,run_name,seed,status";
  for (const std::string& p : study.parameters()) csv += "," + trace::CsvField(p);
  for (const std::string& m : metrics) csv += "," + trace::CsvField(m);
  csv += "\n";
  for (const StudyRun& r : study.runs()) {
    csv += std::to_string(r.id) + "," + trace::CsvField(r.name) + "," + std::to_string(r.seed) + "," + r.status;
    for (const std::string& p : study.parameters()) csv += "," + trace::CsvField(r.values.at(p));
    for (const auto& column : columns) csv += "," + (column.count(r.id) ? Format(column.at(r.id), 15) : "");
    csv += "\n";
  }
  WriteFileAtomically(path, csv);
}

}  // namespace sanet::study
