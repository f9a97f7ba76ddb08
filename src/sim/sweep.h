// Replications: the same scenario run once per seed, one after the other, each into its own
// folder, with the distribution of the time at which the runs ended.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "agents/controller_registry.h"
#include "sim/run_spec.h"

namespace sanet::sim {

struct SweepRun {
  std::uint64_t seed;
  std::string status, ended_by, fingerprint;
  double ended_at = 0;  // s: when the end condition was met, or the duration
  double simulated = 0, wall = 0;
};

struct SweepResult {
  std::vector<SweepRun> runs;
  int ended_by_condition = 0;  // runs that met the scenario's end condition
  double mean = 0, ci95 = 0;   // of the times they met it (s); ci95 is the half-width (Student t)
};

// Runs `spec` for every seed; writes <dir>/seed-<n>/ and <dir>/sweep.csv, <dir>/sweep.json.
// `progress` is called after each run.
SweepResult RunSweep(const RunSpec& spec, const std::vector<std::uint64_t>& seeds, const std::string& dir,
                     const std::string& scenario_file, agents::Registry& registry,
                     const std::function<void(const SweepRun&)>& progress);

// Student's t for a two-sided 95 % interval with `dof` degrees of freedom.
double StudentT95(int dof);

}  // namespace sanet::sim
