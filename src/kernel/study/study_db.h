// A study's results database (study.sqlite), written only by the process that runs the study:
//   study(key, value)                      what the study is: scenario, parameters, command
//   runs(id, name, seed, status, ...)      one row per run, its state and how it went
//   parameters(run, name, value, number)   the varied values of each run
//   scalars(run, name, value)              every number in the run's summary.json, by dotted name
//   results (a view)                       one row per run, with its parameters as columns
// and with `tables`, the runs' per-event CSVs (messages, packets, routes, transitions) with a run
// column. The schema is documented in docs/studies.md.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "study/grid.h"

struct sqlite3;

namespace sanet::study {

class StudyDbError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The folder holds another study (another scenario file, other --set values or varied paths).
class OtherStudy : public StudyDbError {
 public:
  using StudyDbError::StudyDbError;
};

struct StudyInfo {
  std::string scenario;                 // the file
  std::vector<std::string> sets;        // --set common to every run
  std::vector<std::string> parameters;  // the varied paths, in order
  std::string command;
  std::vector<std::string> tables;  // per-event tables to gather
};

// How a run ended, for its row.
struct RunOutcome {
  std::string status;  // completed, failed
  std::string fingerprint, scenario_fingerprint, ended_by, error, host;
  double wall_s = 0, simulated_s = 0, ended_at_s = 0;
  std::string started_utc, finished_utc;
  int rank = 0;  // the MPI rank that ran it (0 without MPI)
};

class StudyDb {
 public:
  // Opens `path`, creating the schema if it is new.
  explicit StudyDb(const std::string& path);
  ~StudyDb();
  StudyDb(const StudyDb&) = delete;
  StudyDb& operator=(const StudyDb&) = delete;

  // A new study records `info`; an existing one must be the same study (scenario, common sets,
  // parameters), or StudyDbError says what differs.
  void Describe(const StudyInfo& info);
  // Adds the runs not there yet, as pending. Runs are matched by name.
  void Plan(const std::vector<RunPoint>& runs);
  std::string Status(const std::string& name) const;  // "" when not planned
  // The fingerprint of the effective scenario a finished run ran ("" before it ends).
  std::string ScenarioFingerprintOf(const std::string& name) const;
  void Started(const std::string& name, const std::string& started_utc);
  void Pending(const std::string& name);  // interrupted: to run again
  // The run's outcome and, when it completed, its summary's numbers and the tables asked for
  // from its folder; all in one transaction.
  void Finished(const std::string& name, const RunOutcome& outcome, const nlohmann::json& summary,
                const std::string& folder);
  // Count of runs per status.
  int Count(const std::string& status) const;
  std::vector<std::string> Tables() const;  // the per-event tables this study gathers

 private:
  void Exec(const std::string& sql) const;
  void CreateSchema();
  void CreateResultsView(const std::vector<std::string>& parameters);
  void Scalars(long run, const nlohmann::json& summary);
  void ImportCsv(long run, const std::string& table, const std::string& path);
  long RunId(const std::string& name) const;
  bool HasTable(const std::string& table) const;
  std::string Get(const std::string& key) const;
  sqlite3* db_ = nullptr;
  std::string path_;
};

// Every number in `j` by dotted name ("network.route_discoveries.time_s.median"); lists and texts
// are left out.
std::vector<std::pair<std::string, double>> Numbers(const nlohmann::json& j);
// The names in summary.json's `nodes` list (none when it has no such list).
std::vector<std::string> NodeNames(const nlohmann::json& summary);

}  // namespace sanet::study
