#include "study_commands.h"

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <thread>

#include "scenario/scenario_loader.h"
#include "study/executor.h"
#include "study/progress.h"
#include "study/report.h"
#include "study/study_mpi.h"
#include "study/sweep.h"

namespace sanet::cli {
namespace {

namespace fs = std::filesystem;

struct SweepArgs {
  std::string file, seeds = "1-10", output, tables;
  std::vector<std::string> sets, vary;
  std::optional<int> jobs;
  std::optional<double> duration;
  std::optional<std::string> threads;
  bool quiet = false, retry_failed = false, force = false;
};

volatile std::sig_atomic_t g_stop = 0;

std::string CommandLine() {
  std::string line;
  std::ifstream in("/proc/self/cmdline");
  for (std::string arg; std::getline(in, arg, '\0');) line += (line.empty() ? "" : " ") + arg;
  return line;
}

std::vector<std::string> ParseTables(const std::string& text) {
  std::vector<std::string> tables;
  std::stringstream parts(text);
  for (std::string t; std::getline(parts, t, ',');) {
    const auto& known = study::GatherableTables();
    if (std::find(known.begin(), known.end(), t) == known.end())
      throw CLI::ValidationError("--tables", "'" + t +
                                                 "' is not a table a study gathers (messages, packets, "
                                                 "routes, transitions)");
    tables.push_back(t);
  }
  return tables;
}

// A study's folder holds study.sqlite, runs/ and logs/; anything else means it is not one.
void CheckStudyFolder(const std::string& dir, bool force) {
  if (!fs::exists(dir)) return;
  if (!fs::is_directory(dir)) throw CLI::ValidationError("--output", dir + " is a file, not a folder");
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name == "study.sqlite" || name == "study.sqlite-journal" || name == "runs" || name == "logs") continue;
    if (!force)
      throw CLI::ValidationError(
          "--output", dir + " holds " + name + ", which is not a study's: give another folder with -o, or --force");
  }
}

study::SweepSettings Settings(const SweepArgs& a, const scenario::Scenario& base) {
  study::SweepSettings s;
  s.scenario = a.file;
  s.sets = a.sets;
  try {
    for (const std::string& v : a.vary) s.parameters.push_back(study::ParseVary(v));
    s.seeds = study::ParseSeeds(a.seeds);
    study::Grid(s.parameters, s.seeds);  // a path varied twice
  } catch (const study::GridError& e) {
    throw CLI::ValidationError(e.what());
  }
  s.duration = a.duration;
  s.threads = a.threads;
  s.folder = a.output.empty() ? base.output_folder + "-sweep" : a.output;
  s.tables = ParseTables(a.tables);
  s.retry_failed = a.retry_failed;
  s.command = CommandLine();
  return s;
}

void PrintEnd(const study::SweepTally& t, const std::string& folder) {
  std::printf("%d of %d runs done: %d completed, %d failed (%d run now)\n", t.completed + t.failed, t.total,
              t.completed, t.failed, t.ran_now);
  if (t.interrupted) std::printf("interrupted: the same command runs the %d left\n", t.total - t.completed - t.failed);
  std::printf("results in %s/ (study.sqlite, runs/, logs/); summarise with: sanet report %s\n", folder.c_str(),
              folder.c_str());
}

int Sweep(const SweepArgs& a, agents::Registry& registry) {
  const scenario::Scenario base = scenario::LoadScenario(a.file, a.sets);
  const study::SweepSettings s = Settings(a, base);
  const int jobs = a.jobs.value_or(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  if (study::UnderMpi() && !study::IsMpiCoordinator()) return study::ServeAsMpiWorker(jobs);
  CheckStudyFolder(s.folder, a.force);
  const std::vector<study::PreparedRun> runs = study::Prepare(s, registry);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, [](int) { g_stop = 1; });
  std::unique_ptr<study::Executor> executor = study::MakeExecutor(jobs);
  if (!a.quiet)
    std::printf("sanet: sweep of %s: %zu runs (%zu combinations x %zu seeds), %s; study in %s/\n",
                base.run.name.c_str(), runs.size(), runs.size() / s.seeds.size(), s.seeds.size(),
                study::Describe(*executor).c_str(), s.folder.c_str());
  std::fflush(stdout);
  study::SweepTally tally;
  {
    study::Progress progress(a.quiet);
    tally = study::RunSweep(
        s, runs, *executor, [] { return g_stop != 0; }, progress.Events());
  }
  executor.reset();  // under MPI: the workers are told to finish
  if (!a.quiet) PrintEnd(tally, s.folder);
  if (tally.interrupted) return kExitInterrupted;
  return tally.failed > 0 ? kExitRunFailed : 0;
}

}  // namespace

Command AddSweep(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Run a study: a scenario for every combination of varied values (--vary), each with every seed, several "
      "at a time, into one results database; run again, it does only what is missing (docs/studies.md)");
  AddScenario(cmd, a->file);
  cmd->add_option("--vary", a->vary,
                  "PATH=V1,V2,...: a scenario value to vary, as --set takes it (repeatable; every combination runs)")
      ->allow_extra_args(false);
  cmd->add_option("--seeds", a->seeds, "Seeds of each combination: a list and/or ranges, e.g. 1-10 or 1,5,9")
      ->capture_default_str();
  cmd->add_option("-j,--jobs", a->jobs,
                  "Runs at a time (default: one per core); under MPI, runs at a time on each rank")
      ->check(CLI::Range(1, 1024));
  AddSet(cmd, a->sets);
  AddDuration(cmd, a->duration);
  AddThreads(cmd, a->threads);
  cmd->add_option("-o,--output", a->output, "The study's folder (default: results/<name>-sweep)");
  cmd->add_option("--tables", a->tables,
                  "Also gather these per-event tables of every run into the database: any of messages, packets, "
                  "routes, transitions, comma-separated");
  cmd->add_flag("--retry-failed", a->retry_failed, "Run again the runs that failed (a finished run is never redone)");
  AddForce(cmd, a->force);
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing but errors");
  return {cmd, [a](agents::Registry& r) { return Sweep(*a, r); }};
}

}  // namespace sanet::cli
