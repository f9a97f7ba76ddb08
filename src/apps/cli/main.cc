// The `sanet` command: parses the command line and calls the kernel; nothing else.
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "agent_command.h"
#include "builtin.h"
#include "core/atomic_file.h"
#include "core/closest_names.h"
#include "core/version.h"
#include "hosting/controller_registry.h"
#include "interruption.h"
#include "launch/launch.h"
#include "launch/namespaces.h"
#include "launch/radio_taps.h"
#include "launch_command.h"
#include "link_curve_command.h"
#include "map_command.h"
#include "merge_command.h"
#include "options.h"
#include "python_controllers/python_controller.h"
#include "robot_server/sim_server.h"
#include "robots/node_model.h"
#include "ros2_options.h"
#include "ros2_presentation/presentation.h"
#include "run_common.h"
#include "scenario/catalogue.h"
#include "scenario/effective_scenario.h"
#include "scenario/scenario_loader.h"
#include "serve_command.h"
#include "sim/radio_calibration.h"
#include "sim/surroundings_of.h"
#include "sim/world.h"
#include "study_commands.h"
#include "terminal_progress.h"
#include "trace/earlier_run.h"
#include "usarsim_agent/remote_node.h"
#include "view/live_view.h"
#include "view/viewer_server.h"
#include "view_options.h"
#include "wire/realtime_priority.h"
#include "wss/wss_server.h"

namespace {

using namespace sanet;

using namespace sanet::cli;

struct RunArgs {
  std::string file;
  std::vector<std::string> sets;
  std::optional<std::uint64_t> seed;
  std::optional<double> duration;
  std::optional<std::string> threads;
  std::string output;
  bool quiet = false;
  bool no_progress = false;
  bool force = false;
  bool isolate_controllers = false;
  bool real_time = false;
  ViewArgs view;
};

// --seed as the scenario's own `seed`: what the loader draws from it (scattered nodes) follows.
std::vector<std::string> WithSeed(std::vector<std::string> sets, const std::optional<std::uint64_t>& seed) {
  if (seed) sets.push_back("seed=" + std::to_string(*seed));
  return sets;
}

int Run(const RunArgs& args, hosting::Registry& registry) {
  scenario::Scenario sc = LoadChecked(args.file, WithSeed(args.sets, args.seed), registry);
  if (args.duration) sc.run.duration = *args.duration;
  if (args.threads) sc.run.threads = std::stoi(*args.threads);
  sc.run.isolate_controllers = args.isolate_controllers;
  sim::RunOptions options;
  options.output_dir = args.output.empty() ? sc.output_folder : args.output;
  options.scenario_file = args.file;
  options.stop_requested = InterruptReason;
  options.force = args.force;
  options.warnings = sc.warnings;
  options.provenance = ProvenanceOf(scenario::Effective(sc));
  ClaimFolder(options.output_dir, args.force);
  if (!args.quiet)
    std::printf("sanet: running %s (%zu node%s, %.1f s simulated, seed %llu%s)\n", sc.run.name.c_str(),
                sc.run.nodes.size(), sc.run.nodes.size() == 1 ? "" : "s", sc.run.duration,
                static_cast<unsigned long long>(sc.run.seed),
                sc.run.threads == 2 ? ", physics on a second thread" : "");
  const net::NetworkSpec* network = sc.run.network ? &*sc.run.network : nullptr;
  if (!args.quiet && network && network->radio_model == net::RadioModel::kAbstract)
    std::printf("  the abstract radio's calibration: %s\n", sim::DescribeCalibration(*network).c_str());
  if (args.real_time) sim::UseRealTimeClock();  // the same schedule, against the wall clock
  sim::World world(sc.run, registry);
  ros2_presentation::RunPresentation ros2_messages(world);  // trace.mcap and the Foxglove stream
  options.trace_files = {ros2_messages.McapFile()};
  LiveViews live = StartLiveViews(world, ros2_messages, args.view);
  if (!args.quiet) live.Announce();
  if (live.foxglove)
    options.add_results = [&](nlohmann::ordered_json& j, trace::ResultsFolder&) {
      j["foxglove"] = live.foxglove->hub().Summary();
    };
  InstallStopHandlers();
  sim::RunResult r;
  {
    TerminalProgress progress(!args.quiet && !args.no_progress && isatty(STDERR_FILENO));
    options.progress = progress.Callback();
    r = world.Run(options);
  }
  live.Finish();
  PrintWarnings(r.warnings);
  if (world.interrupted()) {
    std::fprintf(stderr, "sanet: %s at %.1f s simulated; the results so far are in %s/ (status: interrupted)\n",
                 world.ended_by().c_str(), world.ended_at(), options.output_dir.c_str());
    return 128 + InterruptSignal();
  }
  if (!args.quiet) {
    std::printf("  simulated %.1f s in %.2f s wall (%.1fx real time), %llu events\n", r.simulated, r.wall,
                r.real_time_factor, static_cast<unsigned long long>(r.events));
    if (!world.ended_by().empty()) std::printf("  ended at %.1f s: %s\n", world.ended_at(), world.ended_by().c_str());
    std::printf("  fingerprint %s\n  results in %s/\n", r.fingerprint.c_str(), options.output_dir.c_str());
  }
  return 0;
}

int Validate(const std::string& file, const std::vector<std::string>& sets, bool print, hosting::Registry& registry) {
  const scenario::Scenario sc = LoadChecked(file, sets, registry);
  const net::NetworkSpec* network = sc.run.network ? &*sc.run.network : nullptr;
  const bool abstract = network && network->radio_model == net::RadioModel::kAbstract;
  if (print) {
    std::fputs(scenario::EffectiveScenarioYaml(sc).c_str(), stdout);
    // A comment, so that the printed scenario still loads: where the abstract radio's table comes from.
    if (abstract) std::printf("# network.calibration: %s\n", sim::DescribeCalibration(*network).c_str());
    if (const std::string fixes = sim::DescribeSurroundings(sc.run); !fixes.empty())
      std::printf("# %s\n", fixes.c_str());
    return 0;
  }
  std::size_t robots = 0, controlled = 0;
  for (const auto& n : sc.run.nodes) {
    robots += robots::HasDrive(n.model);
    controlled += n.controller.has_value();
  }
  std::printf("%s: valid: %s (%s, %zu with controllers), %s, %.1f s, seed %llu\n", file.c_str(),
              Count(sc.run.nodes.size(), "node").c_str(), Count(robots, "robot").c_str(), controlled,
              Count(sc.run.obstacles.size(), "obstacle").c_str(), sc.run.duration,
              static_cast<unsigned long long>(sc.run.seed));
  if (abstract) std::printf("  the abstract radio's calibration: %s\n", sim::DescribeCalibration(*network).c_str());
  if (const std::string fixes = sim::DescribeSurroundings(sc.run); !fixes.empty()) std::printf("  %s\n", fixes.c_str());
  return 0;
}

// `sanet list --python MODULE:CLASS`: the module in --python-path's folders or the current one.
hosting::ControllerSpec PythonSpec(const std::string& module_class) {
  hosting::ControllerSpec spec;
  spec.name = spec.python = module_class;
  spec.python_path = PythonPathArgs();
  spec.python_path.push_back(std::filesystem::current_path().string());
  return spec;
}

int List(hosting::Registry& registry, bool markdown, scenario::CatalogueSections sections) {
  std::fputs((markdown ? scenario::ReferenceMarkdown() : scenario::Catalogue(registry, sections)).c_str(), stdout);
  return 0;
}

Command AddRun(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run",
                                     "Run a scenario and write its results folder (trajectories.csv, "
                                     "log.csv, messages.csv, transitions.csv, metrics.csv, summary.json; with "
                                     "outputs.trace, on up to 200 nodes: trace.sqlite and trace.mcap)");
  AddScenario(cmd, a->file);
  AddSet(cmd, a->sets);
  AddPythonPath(cmd);
  cmd->add_option("--seed", a->seed, "Override the scenario's seed (0 to 2^64 - 1)")->check(kSeedText);
  AddDuration(cmd, a->duration);
  AddThreads(cmd, a->threads);
  cmd->add_option("-o,--output", a->output,
                  "Results folder (default: the scenario's outputs.folder, or results/<name>)");
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing but errors");
  cmd->add_flag("--no-progress", a->no_progress, "Do not show progress (shown only on a terminal)");
  cmd->add_flag("--isolate-controllers", a->isolate_controllers,
                "Run each controller in a child process of its own: a plugin that crashes ends the run with its "
                "results kept, not the process (same results; every node call crosses a socket)");
  AddForce(cmd, a->force);
  cmd->add_flag("--real-time", a->real_time,
                "Run against the wall clock, a simulated second per second, to watch it live with --view (the "
                "same results)");
  AddViewOptions(cmd, a->view);
  return {cmd, [a](hosting::Registry& r) { return Run(*a, r); }};
}

Command AddValidate(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  auto sets = std::make_shared<std::vector<std::string>>();
  auto print = std::make_shared<bool>(false);
  auto seed = std::make_shared<std::optional<std::uint64_t>>();
  CLI::App* cmd = app.add_subcommand("validate",
                                     "Check a scenario without running it: structure, types, ranges, "
                                     "models, controllers and their parameters");
  AddScenario(cmd, *file);
  AddSet(cmd, *sets);
  AddPythonPath(cmd);
  cmd->add_option("--seed", *seed, "Seed instead of the scenario's (scattered nodes are drawn from it)")
      ->check(kSeedText);
  cmd->add_flag("--print", *print,
                "Print the effective scenario: every default filled in, grids and scatters as their nodes (it "
                "loads and runs to the same fingerprint)");
  return {cmd, [file, sets, print, seed](hosting::Registry& r) {
            return Validate(*file, WithSeed(*sets, *seed), *print, r);
          }};
}

volatile std::sig_atomic_t g_view_stop = 0;

// The Foxglove replay of the folder's trace.mcap, on a hub of its own; none without the file.
struct Replay {
  std::unique_ptr<foxglove::FoxgloveHub> hub;
  std::unique_ptr<foxglove::McapReplay> replay;  // after the hub: destroyed before the hub it plays on
};

Replay StartFoxgloveReplay(const std::string& results, const FoxgloveArgs& f) {
  Replay r;
  if (!std::filesystem::exists(results + "/trace.mcap")) {
    std::printf("sanet: no trace.mcap in %s: no Foxglove replay (runs write it with outputs.trace)\n", results.c_str());
    return r;
  }
  r.hub = StartHub(f);
  r.replay = StartReplay(results, *r.hub, f);
  if (!r.replay) return r;
  WritePortFile(f.port_file, static_cast<std::uint16_t>(r.hub->port()), "--foxglove-port-file");
  std::printf("sanet: Foxglove replay of %s/trace.mcap (%llu messages, %g x) at ws://127.0.0.1:%d\n", results.c_str(),
              static_cast<unsigned long long>(r.replay->messages()), f.speed, r.hub->port());
  return r;
}

int View(const view::ViewerSettings& settings, const std::string& port_file, const FoxgloveArgs& foxglove) {
  std::signal(SIGINT, [](int) { g_view_stop = 1; });
  std::signal(SIGTERM, [](int) { g_view_stop = 1; });
  const Replay replay = StartFoxgloveReplay(settings.results, foxglove);
  try {
    view::ServeViewer(
        settings,
        [&](int port) {
          WritePortFile(port_file, static_cast<std::uint16_t>(port), "--port-file");
          std::printf("sanet: viewing %s at http://%s:%d/ (Ctrl-C to stop)\n", settings.results.c_str(),
                      settings.bind.c_str(), port);
          std::fflush(stdout);
        },
        [] { return g_view_stop != 0; });
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--port", e.what());
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError("RESULTS_DIR", e.what());
  }
  return 0;
}

Command AddView(CLI::App& app) {
  auto settings = std::make_shared<view::ViewerSettings>();
  auto port_file = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("view",
                                     "Serve a web page (on loopback) that replays a run from its results folder: the "
                                     "world from above and in 3D, radio links and packets, timeline, plots; and "
                                     "its trace.mcap to Foxglove over WebSocket");
  cmd->add_option("results", settings->results, "A results folder with trace.sqlite")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--bind", settings->bind, "Address to listen on (loopback by default)")->capture_default_str();
  cmd->add_option("--port", settings->port, "HTTP port (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  cmd->add_option("--port-file", *port_file, "Once listening, write the port number to this file");
  auto foxglove = std::make_shared<FoxgloveArgs>();
  AddFoxgloveOptions(cmd, *foxglove, /*replay=*/true);
  // The effective scenario the run wrote beside its results, for the radios' ranges. The lambda
  // lives inside *settings, so it holds a plain pointer: a shared_ptr would own itself and leak.
  settings->scenario = [results = &settings->results] {
    const std::string file = *results + "/scenario.yaml";
    if (!std::filesystem::exists(file))
      throw std::runtime_error(file + " not found: no scenario to measure the radio of");
    return scenario::LoadScenario(file).run;
  };
  return {cmd, [settings, port_file, foxglove](hosting::Registry&) { return View(*settings, *port_file, *foxglove); }};
}

Command AddList(CLI::App& app) {
  auto libraries = std::make_shared<std::vector<std::string>>();
  auto markdown = std::make_shared<bool>(false);
  auto pythons = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand("list",
                                     "List the models (with their sensors, limits and body keys), sensor kinds "
                                     "(with their readings, ROS 2 messages and keys) and controllers (with their "
                                     "parameters) that sanet knows");
  cmd->add_option("--library", *libraries, "Also load this controller library (repeatable)");
  cmd->add_option("--python", *pythons,
                  "Also import this Python controller, MODULE:CLASS (repeatable; the module on --python-path or "
                  "in the current folder)");
  AddPythonPath(cmd);
  cmd->add_flag("--markdown", *markdown, "Print the scenario format's reference tables (as in docs/scenario.md)");
  auto only = std::make_shared<scenario::CatalogueSections>(scenario::CatalogueSections{false, false, false});
  cmd->add_flag("--models", only->models, "Print only the models (what each carries, its limits, its body keys)");
  cmd->add_flag("--sensors", only->sensors,
                "Print only the sensor kinds (what each measures, its reading type and units, its ROS 2 message, "
                "its keys)");
  cmd->add_flag("--controllers", only->controllers, "Print only the controllers and their parameters");
  return {cmd, [libraries, pythons, markdown, only](hosting::Registry& r) {
            for (const auto& lib : *libraries) r.LoadLibrary(lib);
            for (const auto& python : *pythons) r.LoadPython(PythonSpec(python));
            const bool some = only->models || only->sensors || only->controllers;
            return List(r, *markdown, some ? *only : scenario::CatalogueSections{});
          }};
}

// Runs the chosen command; errors a user can cause are one line on stderr and an exit code.
int Perform(const Command& command, hosting::Registry& registry) {
  try {
    return command.action(registry);
  } catch (const CLI::ValidationError& e) {
    std::fprintf(stderr, "sanet: error: %s\n", e.what());
    return kExitScenarioError;
  } catch (const scenario::ScenarioError& e) {
    std::fprintf(stderr, "sanet: error: %s\n", e.what());
    return kExitScenarioError;
  } catch (const hosting::RegistryError& e) {
    std::fprintf(stderr, "sanet: error: %s\n", e.what());
    return kExitScenarioError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sanet: run failed: %s\n", e.what());
    return kExitRunFailed;
  }
}

// `sanet runn x`: CLI11 would only say that a subcommand is required; say which one was meant.
bool UnknownCommand(int argc, char** argv, CLI::App& app) {
  if (argc < 2 || argv[1][0] == '-') return false;
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) names.push_back(sub->get_name());
  const std::string wanted = argv[1];
  if (std::find(names.begin(), names.end(), wanted) != names.end()) return false;
  const std::vector<std::string> close = ClosestNames(wanted, names);
  std::fprintf(
      stderr, "sanet: error: '%s' is not a command.%s The commands are %s (sanet --help says what each does).\n",
      wanted.c_str(), close.empty() ? "" : (" Did you mean " + OrList(close) + "?").c_str(), OrList(names).c_str());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  RememberCommandLine(argc, argv);
  CLI::App app{
      "sanet: integrated simulator for sensor/actuator networks and networked robots.\n"
      "Physics (ODE) and network (ns-3) advance on one clock; controllers see one portable interface."};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("sanet ") + SanetVersion() + " (" + SanetCommit() + ")");
  const std::vector<Command> commands = {AddRun(app),   AddValidate(app), AddSweep(app),     AddReport(app),
                                         AddServe(app), AddAgent(app),    AddLaunch(app),    AddList(app),
                                         AddView(app),  AddMerge(app),    AddLinkCurve(app), AddMap(app)};
  if (UnknownCommand(argc, argv, app)) return kExitScenarioError;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, the version or the error
    return code == 0 ? 0 : kExitScenarioError;
  }
  hosting::Registry registry;
  controllers::RegisterBuiltinControllers(registry);
  python_controllers::InstallPython(registry);
  scenario::SetPythonPath(PythonPathArgs());
  for (const Command& c : commands)
    if (*c.app) return Perform(c, registry);
  return kExitRunFailed;
}
