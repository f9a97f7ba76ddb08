#include "launch/launch.h"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/atomic_file.h"
#include "core/closest_names.h"
#include "launch/launch_verdict.h"
#include "launch/namespaces.h"
#include "launch/radio_taps.h"
#include "launch/run_slot.h"

namespace sanet::launch {
namespace {

volatile std::sig_atomic_t g_interrupted = 0;

// In a child of the launcher: becomes `program`, and dies with the launcher even if the launcher
// is killed outright (SIGKILL), so that no server, agent or program is ever left behind.
[[noreturn]] void Exec(const std::string& program, const std::vector<std::string>& args) {
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() == 1) std::_Exit(127);  // the launcher is already gone
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execvp(program.c_str(), argv.data());  // searches PATH for a bare name
  std::_Exit(127);
}

bool SimulatedRadio(const sections::LoopSpec& loop) { return loop.network == sections::LoopNetwork::kSimulated; }

// The simulated radio needs namespaces and taps: without them the run is refused, never moved to
// other links.
void RequireSimulatedRadio() {
  std::string why;
  if (NetworkNamespaces::Permitted(&why) && RadioTapsPermitted(&why)) return;
  if (why.find("root") == std::string::npos)
    why += " (run sanet launch as root, e.g. with sudo, on Linux with network namespaces)";
  throw std::runtime_error("loop.network: simulated needs network namespaces and tap devices: " + why +
                           "; it does not fall back to other links");
}

// Real links between namespaces where the machine allows it; loopback (null) otherwise.
std::unique_ptr<NetworkNamespaces> MakeNamespaces(const RunSlot& slot, const sections::LoopSpec& loop,
                                                  const std::vector<NodeId>& robots) {
  if (SimulatedRadio(loop)) {
    RequireSimulatedRadio();
    auto namespaces = std::make_unique<NetworkNamespaces>(slot, robots, sections::LinkShaping{}, false);
    std::printf("sanet: each agent in its own network namespace; their traffic crosses the simulated radio (%s)\n",
                kRadioInterface);
    return namespaces;
  }
  if (!loop.namespaces) return nullptr;
  std::string why;
  if (!NetworkNamespaces::Permitted(&why)) {
    std::printf(
        "sanet: network namespaces are not available (%s): falling back to loopback, without "
        "netem shaping\n",
        why.c_str());
    return nullptr;
  }
  const sections::LinkShaping& s = loop.shaping;
  const bool wants_shaping = s.delay > 0 || s.jitter > 0 || s.loss > 0 || s.rate > 0;
  std::string no_shaping;
  const bool shape = wants_shaping && NetworkNamespaces::ShapingPermitted(&no_shaping);
  auto namespaces = std::make_unique<NetworkNamespaces>(slot, robots, s, shape);
  std::printf("sanet: each agent in its own network namespace, linked by veth pairs and a bridge\n");
  if (wants_shaping && !shape)
    std::printf(
        "sanet: netem is not available (%s): the links are not shaped; messages.loss and "
        "messages.delay in the scenario impair messages in the agents instead\n",
        no_shaping.c_str());
  return namespaces;
}

// The port a starting server wrote to `path`, or nothing if the server ended (or took more
// than 30 s) before it did.
std::optional<int> WaitForPort(const std::string& path, pid_t server) {
  for (int waited = 0; waited < 30000; waited += 10) {
    std::ifstream in(path);
    int port = 0;
    if (in >> port && port > 0) return port;
    if (::waitpid(server, nullptr, WNOHANG) != 0) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return std::nullopt;
}

// Starts `sanet serve` and returns its process and address. The server tells its port through
// a file, not through text meant for people.
std::pair<pid_t, std::string> StartServer(const std::string& self, const LaunchSettings& settings,
                                          const std::string& bind, const std::vector<std::string>& taps,
                                          bool namespaces, int dds_domain) {
  char port_dir[] = "/tmp/sanet-launch-XXXXXX";
  if (!::mkdtemp(port_dir)) throw std::runtime_error("cannot create a temporary folder for the server's port");
  const std::string port_file = std::string(port_dir) + "/port";
  const pid_t server = ::fork();
  if (server == 0) {
    std::vector<std::string> args = {"sanet", "serve", settings.scenario_file, "--port", "0",           "--bind",
                                     bind,    "-o",    settings.output,        "-q",     "--port-file", port_file};
    if (settings.duration) args.insert(args.end(), {"--duration", std::to_string(*settings.duration)});
    for (const std::string& set : settings.sets) args.insert(args.end(), {"--set", set});
    if (settings.force) args.push_back("--force");
    if (settings.view) args.push_back("--view");
    if (!settings.view) args.push_back("--no-foxglove");  // launch says nothing of Foxglove unless asked
    if (settings.ros2_face) args.insert(args.end(), {"--ros2-domain", std::to_string(dds_domain)});
    for (const std::string& tap : taps) args.insert(args.end(), {"--tap", tap});
    // The scenario's folder is the server's own: the rest of the agents' Python path.
    for (std::size_t i = 1; i < settings.python_path.size(); ++i)
      args.insert(args.end(), {"--python-path", settings.python_path[i]});
    // The face's DDS on the bridge, where the robots' namespaces reach it; not on the host's
    // other interfaces, and never on the robots' radio. CYCLONEDDS_URI is for the programs in the
    // namespaces (sim0, radio0), which the server's namespace does not have.
    if (settings.ros2_face && namespaces) {
      args.insert(args.end(), {"--ros2-interface", bind});
      ::unsetenv("CYCLONEDDS_URI");
    }
    Exec(self, args);
  }
  const std::optional<int> port = WaitForPort(port_file, server);
  std::filesystem::remove_all(port_dir);
  if (!port) {
    ::waitpid(server, nullptr, 0);
    throw std::runtime_error("the server did not start");
  }
  return {server, bind + ":" + std::to_string(*port)};
}

void StartAgent(AgentProcesses& agents, const std::string& self, const LaunchSettings& settings,
                const std::string& robot, const std::string& address, const std::string& namespace_name,
                const std::string& subnet, int udp_base) {
  // The agent fetches the scenario from the server, as one on another computer does.
  std::vector<std::string> args = {"sanet",          "agent", "--server",   address,
                                   "--robot",        robot,   "--udp-base", std::to_string(udp_base),
                                   "--shared-clock", "-q"};
  for (const std::string& folder : settings.python_path) args.insert(args.end(), {"--python-path", folder});
  if (!namespace_name.empty()) {
    args.insert(args.end(), {"--udp-subnet", subnet});
    args[0] = self;  // ip runs the program itself: its path, not a name, comes first
    args.insert(args.begin(), {"ip", "netns", "exec", namespace_name});
  }
  agents.Start(robot, [&] { namespace_name.empty() ? Exec(self, args) : Exec("ip", args); });
}

// " (radio0 10.0.0.3)": where a robot's programs are on the simulated radio, when there is one.
std::string RadioNote(const LaunchSettings& settings, NodeId id) {
  return SimulatedRadio(settings.loop) ? " (radio0 " + RadioAddress(id) + ")" : "";
}

// The user's program, in `robot`'s namespace when it has one, told where it runs through its
// environment: SANET_ROBOT (the robot's name), SANET_SERVER (the server's host:port), over the
// simulated radio SANET_RADIO_ADDRESS (the robot's address on it) and, with the ROS 2 face,
// ROS_DOMAIN_ID (the face's DDS domain).
pid_t StartProgram(const std::vector<std::string>& command, const std::string& robot, NodeId id,
                   const std::string& server, bool radio, const std::string& namespace_name, int dds_domain) {
  const pid_t program = ::fork();
  if (program != 0) return program;
  if (dds_domain >= 0) ::setenv("ROS_DOMAIN_ID", std::to_string(dds_domain).c_str(), 1);
  ::setenv("SANET_ROBOT", robot.c_str(), 1);
  ::setenv("SANET_SERVER", server.c_str(), 1);
  if (radio) ::setenv("SANET_RADIO_ADDRESS", RadioAddress(id).c_str(), 1);
  if (namespace_name.empty()) Exec(command.front(), command);
  std::vector<std::string> args = {"ip", "netns", "exec", namespace_name};
  args.insert(args.end(), command.begin(), command.end());
  Exec("ip", args);
}

void ReportProgram(const std::string& program, const std::string& robot, int status) {
  if (WIFEXITED(status))
    std::printf("  program %s (%s) exited with status %d%s\n", program.c_str(), robot.c_str(), WEXITSTATUS(status),
                WEXITSTATUS(status) == 127 ? " (could not be started)" : "");
  else if (WIFSIGNALED(status))
    std::printf("  program %s (%s) was stopped by signal %d%s\n", program.c_str(), robot.c_str(), WTERMSIG(status),
                WTERMSIG(status) == SIGTERM   ? " at the end of the run"
                : WTERMSIG(status) == SIGKILL ? " (it had not ended 5 s after SIGTERM)"
                                              : "");
}

// Asks every child to end (SIGTERM) and kills (SIGKILL) those that have not 5 s later, so that
// a program that ignores SIGTERM or hangs on its way out never keeps launch from ending. Returns
// each child's wait status, in order.
std::vector<int> StopChildren(const std::vector<pid_t>& children) {
  std::vector<int> status(children.size(), 0);
  std::vector<bool> ended(children.size(), false);
  for (pid_t c : children) ::kill(c, SIGTERM);
  for (int waited = 0; waited <= 5000; waited += 20) {
    bool all = true;
    for (std::size_t i = 0; i < children.size(); ++i) {
      if (!ended[i]) ended[i] = ::waitpid(children[i], &status[i], WNOHANG) == children[i];
      all = all && ended[i];
    }
    if (all) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  for (std::size_t i = 0; i < children.size(); ++i)
    if (!ended[i]) {
      ::kill(children[i], SIGKILL);
      ::waitpid(children[i], &status[i], 0);
    }
  return status;
}

// Waits for the server's run to end; Ctrl-C asks it to end the run and write its results.
int WaitForServer(pid_t server, AgentProcesses& agents) {
  int status = 0;
  bool forwarded = false;
  while (::waitpid(server, &status, WNOHANG) == 0) {
    agents.Watch();
    if (g_interrupted && !forwarded) {
      ::kill(server, SIGINT);
      forwarded = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

// The server runs quietly: its summary says when and why the run ended.
void SayHowTheRunEnded(const std::string& results) {
  std::ifstream in(results + "/summary.json");
  const auto summary = nlohmann::json::parse(in, nullptr, false);
  if (summary.is_discarded() || !summary.contains("ended_at_s")) return;
  const std::string why = summary.value("ended_by", std::string("duration"));
  std::printf("  ended at %.1f s: %s\n", summary["ended_at_s"].get<double>(),
              why == "duration" ? "its duration" : why.c_str());
}

// Ends the programs and the agents still running (the server's run is over) and says how the
// programs ended.
void StopAll(const std::vector<pid_t>& programs, AgentProcesses& agents, const sim::RunSpec& spec,
             const LaunchSettings& settings) {
  std::vector<pid_t> children = programs;
  const std::vector<pid_t> running = agents.StillRunning();
  children.insert(children.end(), running.begin(), running.end());
  const std::vector<int> ended = StopChildren(children);
  for (std::size_t i = 0; i < running.size(); ++i) agents.Stopped(running[i], ended[programs.size() + i]);
  for (std::size_t i = 0; i < programs.size(); ++i)
    ReportProgram(settings.exec_command.front(), spec.nodes[settings.exec_robots[i]].name, ended[i]);
}

// The exit code: the server's when it failed or was interrupted; kExitRobotsMissing when a robot's
// agent failed the run (summary.json names the robot and the agent's last word); else 0.
int Verdict(int server_status, const std::string& results, const AgentProcesses& agents) {
  SayHowTheRunEnded(results);
  std::vector<std::string> failures;
  try {
    failures = JudgeAgents(results, agents.agents());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sanet: cannot add the agents' ends to %s/summary.json: %s\n", results.c_str(), e.what());
  }
  for (const std::string& failure : failures) std::fprintf(stderr, "sanet: %s\n", failure.c_str());
  std::printf("  results in %s/\n", results.c_str());
  if (server_status != 0 && server_status != kExitRobotsMissing) return server_status;
  if (!failures.empty()) {
    std::fprintf(stderr, "sanet: the run failed without %s (status: failed; %s/summary.json)\n",
                 failures.size() == 1 ? "one of its robots" : "some of its robots", results.c_str());
    return kExitRobotsMissing;
  }
  return server_status;
}

}  // namespace

std::vector<NodeId> LaunchedRobots(const sim::RunSpec& spec, bool ros2_face) {
  std::vector<NodeId> robots;
  for (NodeId i = 0; i < spec.nodes.size(); ++i)
    if (sim::RunsAsAgent(spec.nodes[i]) || (ros2_face && robots::HasDrive(spec.nodes[i].model))) robots.push_back(i);
  return robots;
}

std::vector<NodeId> ExecRobots(const sim::RunSpec& spec, bool ros2_face, const std::string& which) {
  const std::vector<NodeId> robots = LaunchedRobots(spec, ros2_face);
  if (which == "all") return robots;
  std::vector<std::string> choices;
  for (NodeId r : robots) choices.push_back(spec.nodes[r].name);
  std::vector<NodeId> chosen;
  std::stringstream names(which);
  for (std::string name; std::getline(names, name, ',');) {
    if (name == "all") throw std::invalid_argument("'all' stands alone: it already names every robot");
    const auto at = std::find(choices.begin(), choices.end(), name);
    if (at == choices.end()) {
      const std::vector<std::string> close = ClosestNames(name, choices);
      throw std::invalid_argument("'" + name + "' is not a robot with a process of its own here (" +
                                  (choices.empty() ? std::string("none") : OrList(choices)) +
                                  "): robots with controllers, and with a ros2 section the others too; or 'all'" +
                                  (close.empty() ? "" : "; did you mean " + OrList(close) + "?"));
    }
    const NodeId id = robots[static_cast<std::size_t>(at - choices.begin())];
    if (std::find(chosen.begin(), chosen.end(), id) != chosen.end())
      throw std::invalid_argument("'" + name + "' is named twice: one program per robot");
    chosen.push_back(id);
  }
  return chosen;
}

int Launch(const sim::RunSpec& spec, const LaunchSettings& settings) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // its lines, its server's and its agents' in order, also piped
  const RunSlot slot = RunSlot::Take();
  const std::vector<NodeId> robots = LaunchedRobots(spec, settings.ros2_face);
  const std::unique_ptr<NetworkNamespaces> namespaces = MakeNamespaces(slot, settings.loop, robots);
  const std::string bind = namespaces ? namespaces->ServerAddress() : "127.0.0.1";
  const std::string self = std::filesystem::read_symlink("/proc/self/exe");
  // Without namespaces the agents' UDP ports are on loopback, which every launch shares.
  const int udp_base = namespaces ? settings.udp_base : slot.UdpBase(settings.udp_base, spec.nodes.size());
  const int dds_domain = settings.ros2_domain >= 0 ? settings.ros2_domain : slot.DdsDomain();
  std::signal(SIGINT, [](int) { g_interrupted = 1; });
  std::signal(SIGTERM, [](int) { g_interrupted = 1; });
  std::vector<std::string> taps;
  if (SimulatedRadio(settings.loop))
    for (NodeId id : robots) taps.push_back(spec.nodes[id].name + "=" + namespaces->Namespace(id));
  const auto [server, address] = StartServer(self, settings, bind, taps, namespaces != nullptr, dds_domain);
  if (settings.ros2_face)
    std::printf("  ROS 2 face on DDS domain %d%s\n", dds_domain,
                settings.ros2_domain >= 0 ? " (the scenario's ros2.domain)" : " (this launch's own)");
  const bool any_agent =
      std::any_of(robots.begin(), robots.end(), [&](NodeId id) { return sim::RunsAsAgent(spec.nodes[id]); });
  if (!namespaces && any_agent) std::printf("  agents on loopback: node i listens on UDP port %d + i\n", udp_base);
  if (namespaces)
    std::printf("  bridge %sbr: the server at %s, node i at %s.(i+1) on sim0\n", slot.NamePrefix().c_str(),
                bind.c_str(), namespaces->Subnet().c_str());
  const std::string subnet = SimulatedRadio(settings.loop) ? kRadioSubnet : namespaces ? namespaces->Subnet() : "";
  AgentProcesses agents;
  for (NodeId id : robots) {
    const std::string& name = spec.nodes[id].name;
    const std::string where = namespaces ? namespaces->Namespace(id) : "";
    if (!sim::RunsAsAgent(spec.nodes[id])) {
      std::printf("  robot %s: driven over ROS 2%s%s\n", name.c_str(),
                  where.empty() ? "" : (", namespace " + where).c_str(), RadioNote(settings, id).c_str());
      continue;
    }
    const bool unreachable = name == settings.test_unreachable;  // port 9 (discard): nothing listens
    StartAgent(agents, self, settings, name, unreachable ? "127.0.0.1:9" : address, where, subnet, udp_base);
    std::printf("  agent %s: process %d%s%s\n", name.c_str(), agents.agents().back().pid,
                where.empty() ? "" : (" in namespace " + where).c_str(), RadioNote(settings, id).c_str());
  }
  std::vector<pid_t> programs;
  for (NodeId id : settings.exec_robots) {
    const std::string where = namespaces ? namespaces->Namespace(id) : "";
    programs.push_back(StartProgram(settings.exec_command, spec.nodes[id].name, id, address,
                                    SimulatedRadio(settings.loop), where, settings.ros2_face ? dds_domain : -1));
    std::printf("  program %s (%s): process %d%s\n", settings.exec_command.front().c_str(), spec.nodes[id].name.c_str(),
                programs.back(), where.empty() ? "" : (" in namespace " + where).c_str());
  }
  std::fflush(stdout);
  const int status = WaitForServer(server, agents);
  StopAll(programs, agents, spec, settings);
  return Verdict(status, settings.output, agents);
}

}  // namespace sanet::launch
