#include "sim/sweep.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "sim/world.h"
#include "trace/csv_sink.h"

namespace sanet::sim {

double StudentT95(int dof) {
  static const double table[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                 2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                 2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof < 1) return 0;
  return dof <= 30 ? table[dof - 1] : 1.96;
}

namespace {

SweepRun RunOne(const RunSpec& spec, std::uint64_t seed, const std::string& dir, const std::string& scenario_file,
                agents::Registry& registry) {
  RunSpec run = spec;
  run.seed = seed;
  SweepRun r{seed, "completed", "duration", ""};
  try {
    World world(run, registry);
    RunOptions options;
    options.output_dir = dir + "/seed-" + std::to_string(seed);
    options.scenario_file = scenario_file;
    const RunResult out = world.Run(options);
    r.simulated = out.simulated;
    r.wall = out.wall;
    r.fingerprint = out.fingerprint;
    r.ended_by = world.ended_by().empty() ? "duration" : world.ended_by();
    r.ended_at = world.ended_by().empty() ? out.simulated : world.ended_at();
  } catch (const std::exception& e) {
    r.status = std::string("failed: ") + e.what();
  }
  return r;
}

// The mean end time of the runs that met their end condition, with its 95 % confidence interval.
void SummariseEnds(const std::vector<double>& ends, SweepResult& result) {
  result.ended_by_condition = static_cast<int>(ends.size());
  if (ends.empty()) return;
  double sum = 0;
  for (double e : ends) sum += e;
  result.mean = sum / ends.size();
  double sq = 0;
  for (double e : ends) sq += (e - result.mean) * (e - result.mean);
  if (ends.size() > 1) {
    const double sd = std::sqrt(sq / (ends.size() - 1));
    result.ci95 = StudentT95(static_cast<int>(ends.size()) - 1) * sd / std::sqrt(double(ends.size()));
  }
}

void WriteSweepFiles(const SweepResult& result, const std::string& dir, const std::string& scenario_file) {
  std::string csv = "seed,status,ended_by,ended_at_s,simulated_s,wall_s,fingerprint\n";
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (const SweepRun& r : result.runs) {
    char row[512];
    std::snprintf(row, sizeof row, "%llu,%s,%s,%.3f,%.3f,%.3f,%s\n", (unsigned long long)r.seed,
                  trace::CsvField(r.status).c_str(), trace::CsvField(r.ended_by).c_str(), r.ended_at, r.simulated,
                  r.wall, r.fingerprint.c_str());
    csv += row;
    runs.push_back({{"seed", r.seed},
                    {"status", r.status},
                    {"ended_by", r.ended_by},
                    {"ended_at_s", r.ended_at},
                    {"simulated_s", r.simulated},
                    {"fingerprint", r.fingerprint}});
  }
  WriteFileAtomically(dir + "/sweep.csv", csv);
  nlohmann::ordered_json j;
  j["scenario"] = scenario_file;
  j["runs"] = result.runs.size();
  j["ended_by_condition"] = result.ended_by_condition;
  j["end_time_s"] = {{"mean", result.mean},
                     {"ci95_half_width", result.ci95},
                     {"ci95", {result.mean - result.ci95, result.mean + result.ci95}}};
  j["per_seed"] = runs;
  WriteFileAtomically(dir + "/sweep.json", j.dump(2) + "\n");
}

}  // namespace

SweepResult RunSweep(const RunSpec& spec, const std::vector<std::uint64_t>& seeds, const std::string& dir,
                     const std::string& scenario_file, agents::Registry& registry,
                     const std::function<void(const SweepRun&)>& progress) {
  std::filesystem::create_directories(dir);
  SweepResult result;
  std::vector<double> ends;
  for (std::uint64_t seed : seeds) {
    const SweepRun r = RunOne(spec, seed, dir, scenario_file, registry);
    if (r.status == "completed" && r.ended_by != "duration") ends.push_back(r.ended_at);
    result.runs.push_back(r);
    if (progress) progress(r);
  }
  SummariseEnds(ends, result);
  WriteSweepFiles(result, dir, scenario_file);
  return result;
}

}  // namespace sanet::sim
