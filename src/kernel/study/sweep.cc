#include "study/sweep.h"

#include <chrono>
#include <deque>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "scenario/effective_scenario.h"
#include "scenario/fields.h"
#include "scenario/scenario_loader.h"
#include "study/folder_message.h"
#include "study/study_db.h"

namespace sanet::study {
namespace {

namespace fs = std::filesystem;

// A value that the scenario refuses, told as the --vary it came from.
[[noreturn]] void RefuseValue(const scenario::ScenarioError& e, const RunPoint& point) {
  for (const auto& [path, value] : point.values)
    if (e.file() == "--set " + path + "=" + value)
      throw scenario::ScenarioError("--vary " + path, 0, e.field(), "the value '" + value + "': " + e.message());
  throw e;
}

std::vector<std::string> AllSets(const SweepSettings& s, const RunPoint& point) {
  std::vector<std::string> sets = s.sets;
  for (const std::string& set : point.Sets()) sets.push_back(set);
  return sets;
}

std::optional<nlohmann::json> ReadSummary(const std::string& folder) {
  std::ifstream in(folder + "/summary.json");
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string Text(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}
double Number(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : 0;
}

RunOutcome OutcomeOf(const JobEnd& end, const std::optional<nlohmann::json>& summary) {
  RunOutcome o;
  o.status = end.completed && summary && Text(*summary, "status") == "completed" ? "completed" : "failed";
  o.error = o.status == "completed" ? "" : end.error.empty() && summary ? Text(*summary, "status") : end.error;
  o.host = end.host;
  o.rank = end.rank;
  o.started_utc = end.started_utc;
  o.finished_utc = end.finished_utc;
  o.wall_s = end.wall_s;
  if (summary) {
    o.fingerprint = Text(*summary, "fingerprint");
    o.scenario_fingerprint = Text(*summary, "scenario_fingerprint");
    o.ended_by = Text(*summary, "ended_by");
    o.ended_at_s = Number(*summary, "ended_at_s");
    o.simulated_s = Number(*summary, "simulated_s");
  }
  return o;
}

// A run the last sweep finished but did not record (it was stopped in between).
bool RecordFromFolder(StudyDb& db, const PreparedRun& run, const std::string& folder) {
  const auto summary = ReadSummary(folder);
  if (!summary || Text(*summary, "status") != "completed" ||
      Text(*summary, "scenario_fingerprint") != run.scenario_fingerprint)
    return false;
  JobEnd end{run.point.name, true, false, "", "", "", "", Number(*summary, "wall_time_s"), 0};
  db.Finished(run.point.name, OutcomeOf(end, summary), *summary, folder);
  return true;
}

RunJob JobFor(const SweepSettings& s, const PreparedRun& run) {
  RunJob job;
  job.name = run.point.name;
  job.folder = fs::absolute(fs::path(s.folder) / "runs" / run.point.name).string();
  job.log = fs::absolute(fs::path(s.folder) / "logs" / (run.point.name + ".txt")).string();
  job.effective_scenario = run.effective_scenario;
  job.args = {"run", fs::absolute(s.scenario).string()};
  for (const std::string& set : AllSets(s, run.point)) job.args.insert(job.args.end(), {"--set", set});
  job.args.insert(job.args.end(), {"--seed", std::to_string(run.point.seed)});
  if (s.duration) job.args.insert(job.args.end(), {"--duration", scenario::ShortNumber(*s.duration)});
  if (s.threads) job.args.insert(job.args.end(), {"--threads", *s.threads});
  for (const std::string& folder : s.python_path) job.args.insert(job.args.end(), {"--python-path", folder});
  job.args.insert(job.args.end(), {"-o", job.folder, "-q", "--no-progress"});
  return job;
}

// The runs still to do; counts the others into `tally`.
std::deque<const PreparedRun*> ToDo(StudyDb& db, const SweepSettings& s, const std::vector<PreparedRun>& runs,
                                    SweepTally& tally) {
  std::deque<const PreparedRun*> queue;
  for (const PreparedRun& run : runs) {
    const std::string status = db.Status(run.point.name);
    const std::string folder = (fs::path(s.folder) / "runs" / run.point.name).string();
    const bool finished = status == "completed" || status == "failed";
    const std::string ran = finished ? db.ScenarioFingerprintOf(run.point.name) : "";
    if (!ran.empty() && ran != run.scenario_fingerprint) {
      ++tally.stale;  // the scenario (its file, or --duration) changed since: its results are not this one's
      queue.push_back(&run);
    } else if (status == "completed" || (status == "failed" && !s.retry_failed)) {
      ++(status == "completed" ? tally.completed : tally.failed);
    } else if (RecordFromFolder(db, run, folder)) {
      ++tally.completed;
    } else {
      queue.push_back(&run);
    }
  }
  return queue;
}

}  // namespace

const std::vector<std::string>& GatherableTables() {
  static const std::vector<std::string> tables = {"messages", "packets", "routes", "transitions"};
  return tables;
}

std::vector<PreparedRun> Prepare(const SweepSettings& s, hosting::Registry& registry) {
  std::vector<PreparedRun> prepared;
  std::string checked;  // the combination loaded last: seeds share it
  scenario::Scenario sc;
  for (const RunPoint& point : Grid(s.parameters, s.seeds)) {
    // Loaded again for every seed: what the loader draws from the seed (scattered nodes) differs.
    const std::string combination = nlohmann::json(point.values).dump() + " seed " + std::to_string(point.seed);
    if (combination != checked) {
      try {
        std::vector<std::string> sets = AllSets(s, point);
        sets.push_back("seed=" + std::to_string(point.seed));
        sc = scenario::LoadScenario(s.scenario, sets);
        scenario::CheckControllers(sc, registry);
      } catch (const scenario::ScenarioError& e) {
        RefuseValue(e, point);
      }
      if (s.duration) sc.run.duration = *s.duration;
      if (s.threads) sc.run.threads = std::stoi(*s.threads);
      checked = combination;
    }
    sc.run.seed = point.seed;
    scenario::EffectiveScenario effective = scenario::Effective(sc);
    prepared.push_back({point, std::move(effective.fingerprint), std::move(effective.yaml)});
  }
  return prepared;
}

SweepTally RunSweep(const SweepSettings& s, const std::vector<PreparedRun>& runs, Executor& executor,
                    const std::function<bool()>& stop, const SweepEvents& events) {
  fs::create_directories(s.folder);
  StudyDb db((fs::path(s.folder) / "study.sqlite").string());
  std::vector<std::string> parameters;
  for (const Parameter& p : s.parameters) parameters.push_back(p.path);
  db.Describe({s.scenario, s.sets, parameters, s.command, s.tables});
  std::vector<RunPoint> points;
  for (const PreparedRun& r : runs) points.push_back(r.point);
  db.Plan(points);
  SweepTally tally;
  tally.total = static_cast<int>(runs.size());
  std::deque<const PreparedRun*> queue = ToDo(db, s, runs, tally);
  events.changed(tally, 0, static_cast<int>(queue.size()));
  while (!queue.empty() || executor.Running() > 0) {
    if (!tally.interrupted && stop()) {
      tally.interrupted = true;
      queue.clear();
      executor.StopAll();
    }
    for (; !queue.empty() && executor.Free() > 0; queue.pop_front()) {
      const RunJob job = JobFor(s, *queue.front());
      fs::remove_all(job.folder);  // the study's own: whatever a stopped run left there goes
      fs::remove_all(IncomingFolder(job.folder));
      db.Started(job.name, UtcNow());
      executor.Start(job);
    }
    for (const JobEnd& end : executor.Poll()) {
      if (end.interrupted) {
        db.Pending(end.name);
        continue;
      }
      const std::string folder = (fs::path(s.folder) / "runs" / end.name).string();
      const std::optional<nlohmann::json> summary = ReadSummary(folder);
      const RunOutcome outcome = OutcomeOf(end, summary);
      db.Finished(end.name, outcome, summary.value_or(nlohmann::json::object()), folder);
      ++(outcome.status == "completed" ? tally.completed : tally.failed);
      ++tally.ran_now;
      events.ended(end.name, outcome.status, end.wall_s);
    }
    events.changed(tally, executor.Running(), static_cast<int>(queue.size()));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return tally;
}

}  // namespace sanet::study
