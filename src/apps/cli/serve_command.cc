// `sanet serve`: a scenario's world in real time for protocol clients (the robot protocol, WSS,
// the ROS 2 face, live views), and the run's verdict on the robots only clients could drive.
#include "serve_command.h"

#include <cstdio>
#include <memory>

#include "interruption.h"
#include "launch/radio_taps.h"
#include "robot_server/sim_server.h"
#include "ros2_options.h"
#include "run_common.h"
#include "view_options.h"
#include "wire/realtime_priority.h"
#include "wss/wss_server.h"

namespace sanet::cli {
namespace {

struct ServeArgs {
  std::vector<std::string> sets;
  std::string file, bind = "127.0.0.1", output, port_file, wss_port_file;
  int port = 3000;
  std::optional<int> wss_port;
  std::optional<int> max_clients, wss_max_clients;
  bool quiet = false, force = false;
  bool no_foxglove = false;  // sanet launch's servers, unless it was asked for a view
  std::optional<double> duration;
  std::vector<std::string> taps;  // NODE=NAMESPACE
  ViewArgs view;
  Ros2Args ros2;
};

// --tap NODE=NAMESPACE: the node's radio reaches a real IP stack in that namespace.
void JoinTaps(sim::World& world, const std::vector<std::string>& taps) {
  if (taps.empty()) return;
  std::string why;
  if (!launch::RadioTapsPermitted(&why)) throw CLI::ValidationError("--tap", why);
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const std::string& t : taps) {
    const auto equals = t.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == t.size())
      throw CLI::ValidationError("--tap", "expected NODE=NAMESPACE, not '" + t + "'");
    pairs.emplace_back(t.substr(0, equals), t.substr(equals + 1));
  }
  try {
    launch::JoinRadioTaps(world.driver(), pairs);
  } catch (const std::exception& e) {
    throw CLI::ValidationError("--tap", e.what());
  }
}

std::size_t WssMaxClients(const ServeArgs& a, const sim::RunSpec& spec) {
  if (!a.wss_port) return 0;
  return a.wss_max_clients ? static_cast<std::size_t>(*a.wss_max_clients) : robot_server::DefaultMaxClients(spec);
}

// --wss-port: a Wireless Simulation Server beside the robot protocol's server.
std::unique_ptr<wss::WssServer> StartWss(sim::World& world, const ServeArgs& a, std::vector<std::string>& notices) {
  if (!a.wss_port) return nullptr;
  wss::WssSettings settings;
  settings.bind = a.bind;
  settings.port = static_cast<std::uint16_t>(*a.wss_port);
  settings.max_clients = WssMaxClients(a, world.spec());
  std::unique_ptr<wss::WssServer> wss;
  try {
    wss = std::make_unique<wss::WssServer>(world.driver(), settings);
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError("--wss-port", e.what());
  }
  WritePortFile(a.wss_port_file, wss->port(), "--wss-port-file");
  wss->Start();
  notices.push_back("sanet: wireless simulation server (WSS) on " + a.bind + ":" + std::to_string(wss->port()));
  return wss;
}

// `yaml`: the effective scenario the server runs; `fingerprint`: that of the scenario as loaded
// (agents compare theirs with it; how long the server runs is its own affair).
robot_server::ServerSettings ServerSettingsFor(const ServeArgs& a, const scenario::Scenario& sc,
                                               const std::string& yaml, const std::string& fingerprint) {
  robot_server::ServerSettings settings;
  settings.bind = a.bind;
  settings.port = static_cast<std::uint16_t>(a.port);
  settings.max_clients =
      a.max_clients ? static_cast<std::size_t>(*a.max_clients) : robot_server::DefaultMaxClients(sc.run);
  settings.scenario_yaml = yaml;
  settings.scenario_fingerprint = fingerprint;
  settings.spawn = sc.spawn;
  settings.announce = !a.quiet;
  try {
    wire::RaiseDescriptorLimit(settings.max_clients + WssMaxClients(a, sc.run));
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError(a.wss_max_clients ? "--max-clients, --wss-max-clients" : "--max-clients", e.what());
  }
  return settings;
}

std::unique_ptr<robot_server::SimServer> StartServer(sim::World& world, const robot_server::ServerSettings& settings) {
  try {
    return std::make_unique<robot_server::SimServer>(world.driver(), settings);
  } catch (const std::runtime_error& e) {
    throw CLI::ValidationError("--port", e.what());
  }
}

void PrintServed(const robot_server::SimServer& server, const sim::RunResult& r, const std::string& results) {
  const auto lag = server.LagSummary();
  std::printf(
      "  served %.1f s; lag behind the wall clock p50 %.4f s, p99 %.4f s, max %.4f s, %lld missed deadlines\n"
      "  results in %s/\n",
      r.simulated, lag["p50_s"].get<double>(), lag["p99_s"].get<double>(), lag["max_s"].get<double>(),
      static_cast<long long>(lag["missed_deadlines"].get<std::int64_t>()), results.c_str());
}

std::string NamesOf(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// The run's verdict on the robots only clients could drive (those with controllers; not those the
// ROS 2 face drove): summary.json's attendance, warnings and, when one never came, its status.
void JudgeAttendance(nlohmann::ordered_json& j, robot_server::Attendance& attendance, const ros2_face::Ros2Face* ros2,
                     double end, bool interrupted) {
  if (ros2) attendance.Excuse(ros2->Driven());
  j["attendance"] = attendance.Summary();
  j["warnings"] = attendance.Warnings(end);
  const std::vector<std::string> never = attendance.NeverDriven();
  if (!never.empty() && !interrupted)
    j["status"] = "failed: no client drove " + NamesOf(never) + ", so " + (never.size() == 1 ? "its" : "their") +
                  " controller" + (never.size() == 1 ? "" : "s") + " never ran";
}

// The world with its servers listening; their notices wait for the serving line, which comes first.
struct Served {
  std::unique_ptr<ros2_presentation::RunPresentation> ros2_messages;  // for trace.mcap and the Foxglove stream
  std::unique_ptr<robot_server::SimServer> server;
  std::unique_ptr<wss::WssServer> wss;
  std::unique_ptr<ros2_face::Ros2Face> ros2;
  LiveViews live;
  std::vector<std::string> notices;
};

Served StartServing(sim::World& world, const ServeArgs& a, const scenario::Scenario& sc,
                    const scenario::EffectiveScenario& effective, const std::string& fingerprint) {
  Served s;
  s.ros2_messages = std::make_unique<ros2_presentation::RunPresentation>(world);
  s.server = StartServer(world, ServerSettingsFor(a, sc, effective.yaml, fingerprint));
  JoinTaps(world, a.taps);
  s.wss = StartWss(world, a, s.notices);
  s.ros2 = StartRos2Face(world, a.ros2, sc.ros2, s.notices);
  s.live = StartLiveViews(world, *s.ros2_messages, a.view, /*foxglove_anyway=*/!a.no_foxglove);
  WritePortFile(a.port_file, s.server->port(), "--port-file");
  return s;
}

sim::RunOptions ServeOptions(const ServeArgs& a, const scenario::Scenario& sc,
                             const scenario::EffectiveScenario& effective, const std::string& results) {
  sim::RunOptions options;
  options.output_dir = results;
  options.scenario_file = a.file;
  options.force = a.force;
  options.warnings = sc.warnings;
  options.provenance = ProvenanceOf(effective);
  options.stop_requested = InterruptReason;
  return options;
}

// How serve ends: interrupted (128 + the signal), without a robot it expected (kExitRobotsMissing),
// or completed (0).
int ServeEnd(sim::World& world, robot_server::SimServer& server, const std::string& results) {
  if (world.interrupted()) {
    std::fprintf(stderr, "sanet: %s at %.1f s; the results so far are in %s/ (status: interrupted)\n",
                 world.ended_by().c_str(), world.ended_at(), results.c_str());
    return 128 + InterruptSignal();
  }
  const std::vector<std::string> never = server.attendance().NeverDriven();
  if (never.empty()) return 0;
  std::fprintf(stderr, "sanet: no client drove %s, so %s never ran (status: failed; %s/summary.json)\n",
               NamesOf(never).c_str(), never.size() == 1 ? "its controller" : "their controllers", results.c_str());
  return kExitRobotsMissing;
}

int Serve(const ServeArgs& a, hosting::Registry& registry) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // its lines and stderr's in the order they happen, also piped
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
  const std::string scheduling = wire::UseRealTimePriority();
  sim::World world(sc.run, registry, sim::RobotDrivers::kFrontEnds);
  Served s = StartServing(world, a, sc, effective, fingerprint);
  s.server->Start();
  InstallStopHandlers();
  std::printf("sanet: serving %s on %s:%u for %.1f s\n", sc.run.name.c_str(), a.bind.c_str(), s.server->port(),
              sc.run.duration);
  if (!a.quiet)
    for (const std::string& notice : s.notices) std::printf("%s\n", notice.c_str());
  if (!a.quiet || a.view.on) s.live.Announce();  // asked for a view, one needs to know where it is
  std::fflush(stdout);
  sim::RunOptions options = ServeOptions(a, sc, effective, results);
  options.trace_files = {s.ros2_messages->McapFile()};
  options.add_results = [&](nlohmann::ordered_json& j, trace::ResultsFolder& folder) {
    j["real_time_lag"] = s.server->LagSummary();
    j["real_time_lag"]["scheduling"] = scheduling;
    j["agents"] = s.server->AgentStats();
    j["clock"] = s.server->ClockSummary();
    if (s.wss) j["wss"] = s.wss->Summary();
    if (s.ros2) j["ros2"] = s.ros2->Summary();
    if (s.live.foxglove) j["foxglove"] = s.live.foxglove->hub().Summary();
    s.server->WriteAgentTable(folder);
    JudgeAttendance(j, s.server->attendance(), s.ros2.get(), world.driver().Now(), world.interrupted());
  };
  const sim::RunResult r = world.Run(options);
  s.live.Finish();
  PrintWarnings(r.warnings);
  if (!a.quiet) PrintServed(*s.server, r, results);
  return ServeEnd(world, *s.server, results);
}

}  // namespace

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
                  "Connections served at once (default: twice the scenario's robots, at least 64); a connection "
                  "silent for 3 s is closed, and one more takes the slot of a client that has not INITed within 3 s, "
                  "or else is answered ERR and closed")
      ->check(CLI::Range(1, 10000));
  cmd->add_flag("-q,--quiet", a->quiet,
                "Print only the serving line, warnings and errors (not the WSS and ROS 2 addresses; the view's "
                "only with --view)");
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
                  "WSS control connections served at once (default: twice the scenario's robots, at least 64); a "
                  "connection silent for 3 s is closed, and one more takes the slot of a client that has not "
                  "registered (INIT) within 3 s, or else is answered ERROR and closed")
      ->check(CLI::Range(1, 10000));
  AddViewOptions(cmd, a->view);
  cmd->add_flag("--no-foxglove", a->no_foxglove,
                "Do not stream to Foxglove (serve does by default; sanet launch's server does only with --view)")
      ->excludes(cmd->get_option("--view"));
  AddRos2Options(cmd, a->ros2);
  return {cmd, [a](hosting::Registry& r) { return Serve(*a, r); }};
}

}  // namespace sanet::cli
