// `sanet sweep`: a study's runs (every combination of the varied values, with every seed), run
// as many at a time as the executor takes, recorded in the study's database as they end. Run
// again with the same command, a study runs only what is missing: runs recorded as finished are
// never redone, and a run whose folder is complete but was not recorded (the sweep was killed
// in between) is recorded from its folder.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hosting/controller_registry.h"
#include "study/executor.h"
#include "study/grid.h"

namespace sanet::study {

struct SweepSettings {
  std::string scenario;               // the file
  std::vector<std::string> sets;      // --set, for every run
  std::vector<Parameter> parameters;  // --vary
  std::vector<std::uint64_t> seeds;
  std::optional<double> duration;
  std::optional<std::string> threads;
  std::string folder;                    // the study's
  std::vector<std::string> tables;       // per-event tables to gather: messages, packets, routes, transitions
  std::vector<std::string> python_path;  // --python-path, given to every run
  bool retry_failed = false;
  std::string command;  // as typed, for the database
};

// A run ready to start: checked (the scenario loads with its values), with what it will be.
struct PreparedRun {
  RunPoint point;
  std::string scenario_fingerprint;
  std::string effective_scenario;
};

// Loads the scenario with each combination's values (any mistake is a ScenarioError naming the
// --vary value) and prepares every run.
std::vector<PreparedRun> Prepare(const SweepSettings& settings, hosting::Registry& registry);

struct SweepTally {
  int total = 0, completed = 0, failed = 0, ran_now = 0;
  int stale = 0;  // finished runs of an earlier version of the scenario, run again
  bool interrupted = false;
};

// What a sweep reports as it goes (study/progress.h draws it).
struct SweepEvents {
  std::function<void(const SweepTally&, int running, int queued)> changed = [](auto&&...) {};
  std::function<void(const std::string& name, const std::string& status, double wall_s)> ended = [](auto&&...) {};
};

// Runs what is missing. `stop` is polled: when it says so, the running runs are stopped (they
// run again next time) and the sweep returns with `interrupted`.
SweepTally RunSweep(const SweepSettings& settings, const std::vector<PreparedRun>& runs, Executor& executor,
                    const std::function<bool()>& stop, const SweepEvents& events);

// The per-event tables a study can gather.
const std::vector<std::string>& GatherableTables();

}  // namespace sanet::study
