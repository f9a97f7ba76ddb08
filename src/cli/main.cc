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
#include "agents/controller_registry.h"
#include "builtin.h"
#include "core/atomic_file.h"
#include "core/closest_names.h"
#include "core/version.h"
#include "interruption.h"
#include "launch/launch.h"
#include "launch/namespaces.h"
#include "launch/radio_taps.h"
#include "merge_command.h"
#include "options.h"
#include "python/python_controller.h"
#include "remote_agent/remote_node.h"
#include "robot_server/sim_server.h"
#include "robots/node_model.h"
#include "ros2_options.h"
#include "scenario/catalogue.h"
#include "scenario/effective_scenario.h"
#include "scenario/scenario_loader.h"
#include "sim/world.h"
#include "study_commands.h"
#include "terminal_progress.h"
#include "trace/earlier_run.h"
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

// What the run's reader should know although nothing failed (also in summary.json).
void PrintWarnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::fprintf(stderr, "sanet: warning: %s\n", w.c_str());
}

sim::Provenance ProvenanceOf(const scenario::EffectiveScenario& effective) {
  return {effective.yaml, effective.fingerprint, CommandLine()};
}

// Before anything is built: the folder must be free for the run (trace/earlier_run.h).
void ClaimFolder(const std::string& dir, bool force) {
  try {
    trace::ClearEarlierRun(dir, force);
  } catch (const trace::FolderRefused& e) {
    throw CLI::ValidationError("--output", e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    throw CLI::ValidationError("--output", "cannot use " + dir + ": " + e.code().message());
  }
}

scenario::Scenario LoadChecked(const std::string& file, const std::vector<std::string>& sets,
                               agents::Registry& registry) {
  scenario::Scenario sc = scenario::LoadScenario(file, sets);
  scenario::CheckControllers(sc, registry);
  for (const std::string& warning : sc.warnings) std::fprintf(stderr, "sanet: warning: %s\n", warning.c_str());
  return sc;
}

int Run(const RunArgs& args, agents::Registry& registry) {
  scenario::Scenario sc = LoadChecked(args.file, args.sets, registry);
  if (args.seed) sc.run.seed = *args.seed;
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
  if (args.real_time) sim::UseRealTimeClock();  // the same schedule, against the wall clock
  sim::World world(sc.run, registry);
  LiveViews live = StartLiveViews(world, args.view, !args.quiet);
  if (!args.quiet) live.AnnounceFoxglove();
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

struct ServeArgs {
  std::vector<std::string> sets;
  std::string file, bind = "127.0.0.1", output, port_file, wss_port_file;
  int port = 3000;
  std::optional<int> wss_port;
  std::optional<int> max_clients, wss_max_clients;
  bool quiet = false, force = false;
  std::optional<double> duration;
  std::vector<std::string> taps;  // NODE=NAMESPACE
  ViewArgs view;
  Ros2Args ros2;
};

// --tap NODE=NAMESPACE: the node's radio reaches a real IP stack in that namespace.
void JoinTaps(sim::World& world, const std::vector<std::string>& taps) {
  if (taps.empty()) return;
  std::string why;
  if (!hil::RadioTapsPermitted(&why)) throw CLI::ValidationError("--tap", why);
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const std::string& t : taps) {
    const auto equals = t.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == t.size())
      throw CLI::ValidationError("--tap", "expected NODE=NAMESPACE, not '" + t + "'");
    pairs.emplace_back(t.substr(0, equals), t.substr(equals + 1));
  }
  try {
    hil::JoinRadioTaps(world.driver(), pairs);
  } catch (const std::exception& e) {
    throw CLI::ValidationError("--tap", e.what());
  }
}

std::size_t WssMaxClients(const ServeArgs& a, const sim::RunSpec& spec) {
  if (!a.wss_port) return 0;
  return a.wss_max_clients ? static_cast<std::size_t>(*a.wss_max_clients) : hil::DefaultMaxClients(spec);
}

// --wss-port: a Wireless Simulation Server beside the robot protocol's server.
std::unique_ptr<hil::WssServer> StartWss(sim::World& world, const ServeArgs& a) {
  if (!a.wss_port) return nullptr;
  hil::WssSettings settings;
  settings.bind = a.bind;
  settings.port = static_cast<std::uint16_t>(*a.wss_port);
  settings.max_clients = WssMaxClients(a, world.spec());
  std::unique_ptr<hil::WssServer> wss;
  try {
    wss = std::make_unique<hil::WssServer>(world.driver(), settings);
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError("--wss-port", e.what());
  }
  WritePortFile(a.wss_port_file, wss->port(), "--wss-port-file");
  wss->Start();
  std::printf("sanet: wireless simulation server (WSS) on %s:%u\n", a.bind.c_str(), wss->port());
  return wss;
}

// `yaml`: the effective scenario the server runs; `fingerprint`: that of the scenario as loaded
// (agents compare theirs with it; how long the server runs is its own affair).
hil::ServerSettings ServerSettingsFor(const ServeArgs& a, const scenario::Scenario& sc, const std::string& yaml,
                                      const std::string& fingerprint) {
  hil::ServerSettings settings;
  settings.bind = a.bind;
  settings.port = static_cast<std::uint16_t>(a.port);
  settings.max_clients = a.max_clients ? static_cast<std::size_t>(*a.max_clients) : hil::DefaultMaxClients(sc.run);
  settings.scenario_yaml = yaml;
  settings.scenario_fingerprint = fingerprint;
  settings.spawn = sc.spawn;
  settings.announce = !a.quiet;
  try {
    hil::RaiseDescriptorLimit(settings.max_clients + WssMaxClients(a, sc.run));
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError(a.wss_max_clients ? "--max-clients, --wss-max-clients" : "--max-clients", e.what());
  }
  return settings;
}

std::unique_ptr<hil::SimServer> StartServer(sim::World& world, const hil::ServerSettings& settings) {
  try {
    return std::make_unique<hil::SimServer>(world.driver(), settings);
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError("--port", e.what());
  }
}

// `over_ros2`: robots the ROS 2 face drove, which no protocol client needed to.
void PrintServed(const hil::SimServer& server, const sim::RunResult& r, const std::string& results,
                 const std::vector<std::string>& over_ros2) {
  const auto lag = server.LagSummary();
  std::printf(
      "  served %.1f s; lag behind the wall clock p50 %.4f s, p99 %.4f s, max %.4f s, %lld missed deadlines\n"
      "  results in %s/\n",
      r.simulated, lag["p50_s"].get<double>(), lag["p99_s"].get<double>(), lag["max_s"].get<double>(),
      static_cast<long long>(lag["missed_deadlines"].get<std::int64_t>()), results.c_str());
  std::string idle;
  for (const std::string& name : server.NeverDriven())
    if (std::find(over_ros2.begin(), over_ros2.end(), name) == over_ros2.end())
      idle += (idle.empty() ? "" : ", ") + name;
  if (!idle.empty()) std::printf("  no client drove %s: their controllers never ran\n", idle.c_str());
}

int Serve(const ServeArgs& a, agents::Registry& registry) {
  scenario::Scenario sc = LoadChecked(a.file, a.sets, registry);
  // Agents with their own copy of the file compare this; how long the server runs is its own affair.
  scenario::EffectiveScenario effective = scenario::Effective(sc);
  const std::string fingerprint = effective.fingerprint;
  if (a.duration && *a.duration != sc.run.duration) {
    sc.run.duration = *a.duration;
    effective = scenario::Effective(sc);
  }
  const std::string results = a.output.empty() ? sc.output_folder : a.output;
  ClaimFolder(results, a.force);
  sim::UseRealTimeClock();  // the same schedule, run against the wall clock
  const std::string scheduling = hil::UseRealTimePriority();
  sim::World world(sc.run, registry, sim::RobotDrivers::kFrontEnds);
  const std::unique_ptr<hil::SimServer> listening =
      StartServer(world, ServerSettingsFor(a, sc, effective.yaml, fingerprint));
  hil::SimServer& server = *listening;
  JoinTaps(world, a.taps);
  const std::unique_ptr<hil::WssServer> wss = StartWss(world, a);
  const std::unique_ptr<ros2face::Ros2Face> ros2 = StartRos2Face(world, a.ros2, sc.ros2);
  LiveViews live = StartLiveViews(world, a.view, /*announce=*/true, /*foxglove_anyway=*/true);
  WritePortFile(a.port_file, server.port(), "--port-file");
  server.Start();
  InstallStopHandlers();
  std::printf("sanet: serving %s on %s:%u for %.1f s\n", sc.run.name.c_str(), a.bind.c_str(), server.port(),
              sc.run.duration);
  std::fflush(stdout);
  live.AnnounceFoxglove();
  sim::RunOptions options;
  options.output_dir = results;
  options.scenario_file = a.file;
  options.force = a.force;
  options.warnings = sc.warnings;
  options.provenance = ProvenanceOf(effective);
  options.stop_requested = InterruptReason;
  options.add_results = [&](nlohmann::ordered_json& j, trace::ResultsFolder& folder) {
    j["real_time_lag"] = server.LagSummary();
    j["real_time_lag"]["scheduling"] = scheduling;
    j["agents"] = server.AgentStats();
    j["clock"] = server.ClockSummary();
    if (wss) j["wss"] = wss->Summary();
    if (ros2) j["ros2"] = ros2->Summary();
    if (live.foxglove) j["foxglove"] = live.foxglove->hub().Summary();
    server.WriteAgentTable(folder);
  };
  const sim::RunResult r = world.Run(options);
  live.Finish();
  PrintWarnings(r.warnings);
  if (!a.quiet) PrintServed(server, r, results, ros2 ? ros2->Driven() : std::vector<std::string>{});
  if (world.interrupted()) {
    std::fprintf(stderr, "sanet: %s at %.1f s; the results so far are in %s/ (status: interrupted)\n",
                 world.ended_by().c_str(), world.ended_at(), results.c_str());
    return 128 + InterruptSignal();
  }
  return 0;
}

struct LaunchArgs {
  std::string file, output, exec_robot;
  std::vector<std::string> sets;
  std::optional<int> udp_base;
  std::optional<double> duration;
  std::vector<std::string> command;
  bool force = false;
};

int Launch(const LaunchArgs& a, agents::Registry& registry) {
  const scenario::Scenario sc = LoadChecked(a.file, a.sets, registry);
  if (!a.command.empty() && a.exec_robot.empty())
    throw CLI::ValidationError("--exec", "a command after -- runs in robots' namespaces: name them with --exec ROBOT");
  if (!a.exec_robot.empty() && a.command.empty())
    throw CLI::ValidationError("--exec", "give the program to run after --, e.g. --exec r1 -- ping 10.0.0.2");
  std::vector<NodeId> exec_robots;
  try {
    if (!a.exec_robot.empty()) exec_robots = hil::ExecRobots(sc.run, sc.ros2.has_value(), a.exec_robot);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--exec", e.what());
  }
  const int udp_base = a.udp_base.value_or(sc.loop.udp_port);
  if (sc.loop.network == sections::LoopNetwork::kSimulated && sc.run.network &&
      (udp_base == sc.run.network->port || udp_base == net::kAodvPort || udp_base == net::kOlsrPort ||
       udp_base == net::kDsdvPort))
    throw CLI::ValidationError(
        "--udp-base", std::to_string(udp_base) + " is network.port, which the simulated network serves itself");
  hil::LaunchSettings settings;
  settings.scenario_file = a.file;
  settings.sets = a.sets;
  settings.output = a.output.empty() ? sc.output_folder : a.output;
  settings.force = a.force;
  ClaimFolder(settings.output, a.force);
  settings.loop = sc.loop;
  settings.udp_base = udp_base;
  settings.duration = a.duration;
  settings.ros2_face = sc.ros2.has_value();
  settings.exec_robots = exec_robots;
  settings.exec_command = a.command;
  settings.python_path = {std::filesystem::absolute(a.file).parent_path().string()};
  for (const std::string& folder : PythonPathArgs()) settings.python_path.push_back(folder);
  return hil::Launch(sc.run, settings);
}

int Validate(const std::string& file, const std::vector<std::string>& sets, bool print, agents::Registry& registry) {
  const scenario::Scenario sc = LoadChecked(file, sets, registry);
  if (print) {
    std::fputs(scenario::EffectiveScenarioYaml(sc).c_str(), stdout);
    return 0;
  }
  std::size_t robots = 0, controlled = 0;
  for (const auto& n : sc.run.nodes) {
    robots += n.model.kind != robots::ModelKind::kMote;
    controlled += n.controller.has_value();
  }
  std::printf("%s: valid: %s (%s, %zu with controllers), %s, %.1f s, seed %llu\n", file.c_str(),
              Count(sc.run.nodes.size(), "node").c_str(), Count(robots, "robot").c_str(), controlled,
              Count(sc.run.obstacles.size(), "obstacle").c_str(), sc.run.duration,
              static_cast<unsigned long long>(sc.run.seed));
  return 0;
}

// `sanet list --python MODULE:CLASS`: the module in --python-path's folders or the current one.
agents::ControllerSpec PythonSpec(const std::string& module_class) {
  agents::ControllerSpec spec;
  spec.name = spec.python = module_class;
  spec.python_path = PythonPathArgs();
  spec.python_path.push_back(std::filesystem::current_path().string());
  return spec;
}

int List(agents::Registry& registry, bool markdown) {
  std::fputs((markdown ? scenario::ReferenceMarkdown() : scenario::Catalogue(registry)).c_str(), stdout);
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
  return {cmd, [a](agents::Registry& r) { return Run(*a, r); }};
}

Command AddValidate(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  auto sets = std::make_shared<std::vector<std::string>>();
  auto print = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("validate",
                                     "Check a scenario without running it: structure, types, ranges, "
                                     "models, controllers and their parameters");
  AddScenario(cmd, *file);
  AddSet(cmd, *sets);
  AddPythonPath(cmd);
  cmd->add_flag("--print", *print,
                "Print the effective scenario: every default filled in, grids as their nodes (it loads and runs "
                "to the same fingerprint)");
  return {cmd, [file, sets, print](agents::Registry& r) { return Validate(*file, *sets, *print, r); }};
}

Command AddServe(CLI::App& app) {
  auto a = std::make_shared<ServeArgs>();
  CLI::App* cmd = app.add_subcommand("serve",
                                     "Serve a scenario's world in real time over the robot protocol "
                                     "(USARSim-compatible; docs/protocol.md): clients drive its robots");
  AddScenario(cmd, a->file);
  AddSet(cmd, a->sets);
  AddPythonPath(cmd);
  cmd->add_option("--bind", a->bind, "Address to listen on (loopback by default)")->capture_default_str();
  cmd->add_option("--port", a->port, "TCP port (0: any free port)")->check(CLI::Range(0, 65535))->capture_default_str();
  cmd->add_option(
      "--port-file", a->port_file,
      "Once listening, write the port number to this file (for programs that start the server with --port 0)");
  cmd->add_option("-o,--output", a->output, "Results folder (default: the scenario's)");
  cmd->add_option("--max-clients", a->max_clients,
                  "Connections served at once (default: twice the scenario's robots, at least 64); one more is "
                  "answered ERR and closed")
      ->check(CLI::Range(1, 10000));
  cmd->add_flag("-q,--quiet", a->quiet, "Print only the listening line and errors");
  AddForce(cmd, a->force);
  AddDuration(cmd, a->duration);
  cmd->add_option("--tap", a->taps,
                  "NODE=NAMESPACE: give the network namespace an interface radio0 with the node's (a robot's or a "
                  "mote's) address on the simulated radio, carried by ns-3 (needs root and /dev/net/tun; sanet launch "
                  "does this for "
                  "loop.network: simulated)");
  cmd->add_option("--wss-port", a->wss_port,
                  "Also serve USARSim's Wireless Simulation Server protocol on this TCP port (its default is 50000; "
                  "0: any free port), with signal strengths and links from the simulated radio")
      ->check(CLI::Range(0, 65535));
  cmd->add_option("--wss-port-file", a->wss_port_file, "Once listening, write the WSS port number to this file");
  cmd->add_option("--wss-max-clients", a->wss_max_clients,
                  "WSS control connections served at once (default: twice the scenario's robots, at least 64); one "
                  "more is answered ERROR and closed")
      ->check(CLI::Range(1, 10000));
  AddViewOptions(cmd, a->view);
  AddRos2Options(cmd, a->ros2);
  return {cmd, [a](agents::Registry& r) { return Serve(*a, r); }};
}

Command AddLaunch(CLI::App& app) {
  auto a = std::make_shared<LaunchArgs>();
  CLI::App* cmd = app.add_subcommand("launch",
                                     "Start a server and one agent process per robot on this machine, run "
                                     "the scenario in real time, stop them all (also on Ctrl-C)");
  AddScenario(cmd, a->file);
  AddSet(cmd, a->sets);
  AddPythonPath(cmd);
  cmd->add_option("-o,--output", a->output, "Results folder (default: the scenario's)");
  AddDuration(cmd, a->duration);
  cmd->add_option("--udp-base", a->udp_base, "UDP port of node 0 (default: the scenario's loop.udp_port, 47000)")
      ->check(CLI::Range(1024, 60000));
  cmd->add_option("--exec", a->exec_robot,
                  "Run the program given after -- beside the agents, once per robot named (ROBOT,ROBOT... or all: "
                  "robots with controllers and, with a ros2 section, the others too), in its network namespace "
                  "(with loop.namespaces or loop.network: simulated), with SANET_ROBOT, SANET_SERVER and "
                  "SANET_RADIO_ADDRESS set; stopped when the run ends");
  cmd->add_option("command", a->command, "The program and its arguments for --exec, after --");
  AddForce(cmd, a->force);
  return {cmd, [a](agents::Registry& r) { return Launch(*a, r); }};
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
  return {cmd, [settings, port_file, foxglove](agents::Registry&) { return View(*settings, *port_file, *foxglove); }};
}

Command AddList(CLI::App& app) {
  auto libraries = std::make_shared<std::vector<std::string>>();
  auto markdown = std::make_shared<bool>(false);
  auto pythons = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand("list",
                                     "List the models (with their body keys), sensors (with their keys) and "
                                     "controllers (with their parameters) that sanet knows");
  cmd->add_option("--library", *libraries, "Also load this controller library (repeatable)");
  cmd->add_option("--python", *pythons,
                  "Also import this Python controller, MODULE:CLASS (repeatable; the module on --python-path or "
                  "in the current folder)");
  AddPythonPath(cmd);
  cmd->add_flag("--markdown", *markdown, "Print the scenario format's reference tables (as in docs/scenario.md)");
  return {cmd, [libraries, pythons, markdown](agents::Registry& r) {
            for (const auto& lib : *libraries) r.LoadLibrary(lib);
            for (const auto& python : *pythons) r.LoadPython(PythonSpec(python));
            return List(r, *markdown);
          }};
}

// Runs the chosen command; errors a user can cause are one line on stderr and an exit code.
int Perform(const Command& command, agents::Registry& registry) {
  try {
    return command.action(registry);
  } catch (const CLI::ValidationError& e) {
    std::fprintf(stderr, "sanet: error: %s\n", e.what());
    return kExitScenarioError;
  } catch (const scenario::ScenarioError& e) {
    std::fprintf(stderr, "sanet: error: %s\n", e.what());
    return kExitScenarioError;
  } catch (const agents::RegistryError& e) {
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
  const std::vector<Command> commands = {AddRun(app),   AddValidate(app), AddSweep(app), AddReport(app), AddServe(app),
                                         AddAgent(app), AddLaunch(app),   AddList(app),  AddView(app),   AddMerge(app)};
  if (UnknownCommand(argc, argv, app)) return kExitScenarioError;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, the version or the error
    return code == 0 ? 0 : kExitScenarioError;
  }
  agents::Registry registry;
  controllers::RegisterBuiltinControllers(registry);
  python::InstallPython(registry);
  scenario::SetPythonPath(PythonPathArgs());
  for (const Command& c : commands)
    if (*c.app) return Perform(c, registry);
  return kExitRunFailed;
}
