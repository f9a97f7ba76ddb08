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
#include "study/study_db.h"
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

// A study's folder is one that holds study.sqlite (with whatever its user put beside it, such as
// plots) or nothing yet; a folder with other files and no study is someone else's.
void CheckStudyFolder(const std::string& dir, bool force) {
  if (!fs::exists(dir)) return;
  if (!fs::is_directory(dir)) throw CLI::ValidationError("--output", dir + " is a file, not a folder");
  if (fs::exists(fs::path(dir) / "study.sqlite") || force) return;
  for (const auto& entry : fs::directory_iterator(dir))
    throw CLI::ValidationError("--output", dir + " holds " + entry.path().filename().string() +
                                               " and no study (study.sqlite): give another folder with -o, or "
                                               "--force to start a study there");
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
  for (const std::string& folder : PythonPathArgs())
    s.python_path.push_back(std::filesystem::absolute(folder).string());
  s.retry_failed = a.retry_failed;
  for (const std::string& arg : CommandLine()) s.command += (s.command.empty() ? "" : " ") + arg;
  return s;
}

void PrintEnd(const study::SweepTally& t, const std::string& folder, bool has_end_condition) {
  if (t.stale > 0)
    std::printf("%s of an earlier version of the scenario (another file or --duration) ran again\n",
                Count(t.stale, "finished run").c_str());
  std::printf("%d of %s done: %d completed, %d failed (%d run by this command)\n", t.completed + t.failed,
              Count(t.total, "run").c_str(), t.completed, t.failed, t.ran_now);
  if (has_end_condition && t.completed > 0) {
    const std::vector<double> times = study::StudyReader(folder).EndConditionTimes();
    const MeanCi end = MeanWithCi(times);
    std::printf("the end condition was met in %zu of %d completed runs", times.size(), t.completed);
    if (end.count > 1)
      std::printf(", at %.1f s on average (95%% confidence interval %.1f to %.1f s)", end.mean,
                  end.mean - end.half_width, end.mean + end.half_width);
    std::printf("\n");
  }
  if (t.interrupted) std::printf("interrupted: the same command runs the %d left\n", t.total - t.completed - t.failed);
  std::printf("results in %s/ (study.sqlite, runs/, logs/); summarise with: sanet report %s\n", folder.c_str(),
              folder.c_str());
}

int Sweep(const SweepArgs& a, hosting::Registry& registry) {
  const scenario::Scenario base = scenario::LoadScenario(a.file, a.sets);
  const study::SweepSettings s = Settings(a, base);
  // Under MPI the ranks are the parallelism (one per core, as mpirun places them): one run each.
  const int jobs =
      a.jobs.value_or(study::UnderMpi() ? 1 : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  if (study::UnderMpi() && !study::IsMpiCoordinator()) return study::ServeAsMpiWorker(jobs);
  CheckStudyFolder(s.folder, a.force);
  const std::vector<study::PreparedRun> runs = study::Prepare(s, registry);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, [](int) { g_stop = 1; });
  std::unique_ptr<study::Executor> executor = study::MakeExecutor(jobs);
  if (!a.quiet)
    std::printf("sanet: sweep of %s: %s (%s x %s), %s; study in %s/\n", base.run.name.c_str(),
                Count(runs.size(), "run").c_str(), Count(runs.size() / s.seeds.size(), "combination").c_str(),
                Count(s.seeds.size(), "seed").c_str(), study::Describe(*executor).c_str(), s.folder.c_str());
  std::fflush(stdout);
  study::SweepTally tally;
  {
    study::Progress progress(a.quiet);
    try {
      tally = study::RunSweep(
          s, runs, *executor, [] { return g_stop != 0; }, progress.Events());
    } catch (const study::OtherStudy& e) {
      throw CLI::ValidationError("--output", e.what());
    }
  }
  executor.reset();  // under MPI: the workers are told to finish
  if (!a.quiet) PrintEnd(tally, s.folder, base.run.HasEndCondition());
  if (tally.interrupted) return kExitInterrupted;
  return tally.failed > 0 ? kExitRunFailed : 0;
}

struct ReportArgs {
  std::string study, by, plot, csv;
  std::vector<std::string> metrics, derive;
  study::PlotText text;
  bool list = false, per_node = false;
};

int List(const study::StudyReader& study, bool per_node) {
  std::printf("parameters:%s\n", study.parameters().empty() ? " (none: seeds only)" : "");
  for (const std::string& p : study.parameters()) std::printf("  %s\n", p.c_str());
  std::printf("runs: %zu\nmetrics (completed runs that have each%s):\n", study.runs().size(),
              per_node ? "" : "; per-node metrics folded over the nodes, --per-node for each node's");
  for (const auto& m : study.Metrics(per_node)) {
    const std::string nodes = m.nodes > 0 ? "  (" + Count(m.nodes, "node") + ")" : "";
    std::printf("  %-60s %d%s\n", m.name.c_str(), m.runs, nodes.c_str());
  }
  if (!study.definitions().empty()) std::printf("derived (--derive):\n");
  for (const auto& [name, expression] : study.definitions())
    std::printf("  %-20s = %s\n", name.c_str(), expression.c_str());
  return 0;
}

void Define(study::StudyReader& study, const std::vector<std::string>& derive) {
  for (const std::string& d : derive) {
    const std::size_t eq = d.find('=');
    if (eq == std::string::npos) throw study::ReportError("--derive takes NAME=EXPRESSION, not '" + d + "'");
    const auto trimmed = [](std::string t) {
      t.erase(0, t.find_first_not_of(" \t"));
      t.erase(t.find_last_not_of(" \t") + 1);
      return t;
    };
    study.Define(trimmed(d.substr(0, eq)), trimmed(d.substr(eq + 1)));
  }
}

// Runs that completed but gave the metric no value (docs/studies.md#expressions says when).
void NoteMissing(const study::StudyReader& study, const std::string& metric, std::size_t with_value) {
  const int without = study.CompletedRuns() - static_cast<int>(with_value);
  if (without > 0)
    std::fprintf(stderr,
                 "note: %d of %d completed runs %s no value of %s (they lack a metric it reads, mean/min/max match "
                 "nothing in them, or the result is not a finite number, as after a division by 0); they are left "
                 "out\n",
                 without, study.CompletedRuns(), without == 1 ? "has" : "have", metric.c_str());
}

void Csv(const study::StudyReader& study, const ReportArgs& a) {
  std::vector<std::string> metrics = a.metrics;
  if (metrics.empty())
    for (const auto& m : study.Metrics(a.per_node))
      if (m.name != "seed") metrics.push_back(m.name);  // summary.json's seed: the seed column already
  study::WriteCsv(study, metrics, a.csv);
  std::printf("runs in %s\n", a.csv.c_str());
}

int Report(const ReportArgs& a) {
  try {
    study::StudyReader study(a.study);
    Define(study, a.derive);
    if (a.list || (a.metrics.empty() && a.csv.empty())) return List(study, a.per_node);
    if (!a.plot.empty()) study::CheckPlotName(a.plot);
    const std::string by =
        study.Parameter(a.by.empty() && !study.parameters().empty() ? study.parameters().front() : a.by);
    std::vector<study::MetricSeries> plotted;
    std::string few;  // said once, after the tables, whatever the metrics
    for (const std::string& metric : a.metrics) {
      plotted.push_back({metric, study::Summarise(study, metric, by)});
      std::fputs(study::FormatTable(metric, by, plotted.back().series).c_str(), stdout);
      std::size_t with_value = 0;
      for (const study::Series& s : plotted.back().series)
        for (const study::Point& p : s.points) with_value += static_cast<std::size_t>(p.stats.count);
      NoteMissing(study, metric, with_value);
      if (few.empty()) few = study::FewRunsWarning(plotted.back().series);
    }
    std::fflush(stdout);
    std::fputs(few.c_str(), stderr);
    if (!a.plot.empty() && !plotted.empty()) {
      study::Plot(plotted, by, a.text, a.plot);
      std::printf("plot in %s\n", a.plot.c_str());
    }
    if (!a.csv.empty()) Csv(study, a);
  } catch (const study::ReportError& e) {
    throw CLI::ValidationError(e.what());
  }
  return 0;
}

}  // namespace

Command AddReport(CLI::App& app) {
  auto a = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Summarise a study (sanet sweep): a metric against a varied parameter with mean and 95% confidence "
      "interval per value, as a table, a plot (SVG/PNG) and CSV (docs/studies.md)");
  cmd->add_option("study", a->study, "The study's folder (or its study.sqlite)")->required();
  cmd->add_option("-m,--metric", a->metrics,
                  "A number of the runs' summary.json by dotted name (network.route_discoveries.time_s.median), an "
                  "expression (sum(metrics.m*.created.count)) or a --derive name (repeatable; --list shows them)");
  cmd->add_option("--derive", a->derive,
                  "NAME=EXPRESSION: a metric of each run computed from its others, e.g. "
                  "delivery=sum(metrics.mule.delivered.sum)/sum(metrics.m*.created.count): + - * / ( ), numbers, "
                  "metrics, and sum mean min max count over a pattern with * (repeatable; docs/studies.md)");
  cmd->add_option("--by", a->by, "The varied parameter on the x axis (default: the first one varied)");
  cmd->add_option("--plot", a->plot, "Plot every -m into this .svg or .png file, a line each");
  cmd->add_option("--title", a->text.title, "The plot's title (default: what it shows)");
  cmd->add_option("--xlabel", a->text.xlabel, "The plot's x axis label (default: the parameter's last path part)");
  cmd->add_option("--ylabel", a->text.ylabel, "The plot's y axis label (default: the metric, or 'value' for several)");
  cmd->add_option("--csv", a->csv,
                  "Write one row per run (run_id, run_name, seed, status, parameters and the -m metrics, or every "
                  "metric without -m) for pandas or a spreadsheet");
  cmd->add_flag("--list", a->list, "List the study's parameters and metrics");
  cmd->add_flag("--per-node", a->per_node,
                "List (and write to --csv) each node's metrics, not the per-node metrics folded over the nodes");
  return {cmd, [a](hosting::Registry&) { return Report(*a); }};
}

Command AddSweep(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Run a study: a scenario for every combination of varied values (--vary), each with every seed, several "
      "at a time, into one results database; run again, it does only what is missing (docs/studies.md)");
  AddScenario(cmd, a->file);
  AddPythonPath(cmd);
  cmd->add_option("--vary", a->vary,
                  "PATH=V1,V2,...: a scenario value to vary, as --set takes it (repeatable; every combination runs)")
      ->allow_extra_args(false);
  cmd->add_option("--seeds", a->seeds, "Seeds of each combination: a list and/or ranges, e.g. 1-10 or 1,5,9")
      ->capture_default_str();
  cmd->add_option(
         "-j,--jobs", a->jobs,
         "Runs at a time (default: one per core); under MPI, runs at a time on each rank (default 1: one rank per "
         "core)")
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
  return {cmd, [a](hosting::Registry& r) { return Sweep(*a, r); }};
}

}  // namespace sanet::cli
