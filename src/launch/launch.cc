#include "launch/launch.h"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/atomic_file.h"
#include "launch/namespaces.h"
#include "launch/radio_taps.h"

namespace sanet::hil {
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

std::vector<NodeId> RobotsWithControllers(const sim::RunSpec& spec) {
  std::vector<NodeId> robots;
  for (NodeId i = 0; i < spec.nodes.size(); ++i)
    if (sim::RunsAsAgent(spec.nodes[i])) robots.push_back(i);
  return robots;
}

// --exec ROBOT: one of the robots that run as agents.
std::optional<NodeId> ExecRobot(const sim::RunSpec& spec, const LaunchSettings& settings,
                                const std::vector<NodeId>& robots) {
  if (settings.exec_command.empty()) return std::nullopt;
  for (NodeId id : robots)
    if (spec.nodes[id].name == settings.exec_robot) return id;
  std::string names;
  for (NodeId id : robots) names += (names.empty() ? "" : ", ") + spec.nodes[id].name;
  throw std::runtime_error("--exec " + settings.exec_robot + ": not one of the robots that run as agents (" + names +
                           ")");
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
std::unique_ptr<NetworkNamespaces> MakeNamespaces(const sections::LoopSpec& loop, const std::vector<NodeId>& robots) {
  if (SimulatedRadio(loop)) {
    RequireSimulatedRadio();
    auto namespaces = std::make_unique<NetworkNamespaces>(robots, sections::LinkShaping{}, false);
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
  auto namespaces = std::make_unique<NetworkNamespaces>(robots, s, shape);
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
                                          const std::string& bind, const std::vector<std::string>& taps) {
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
    for (const std::string& tap : taps) args.insert(args.end(), {"--tap", tap});
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

pid_t StartAgent(const std::string& self, const LaunchSettings& settings, const std::string& robot,
                 const std::string& address, const std::string& namespace_name, const std::string& subnet) {
  const pid_t agent = ::fork();
  if (agent != 0) return agent;
  // The agent fetches the scenario from the server, as one on another computer does.
  std::vector<std::string> args = {"sanet",          "agent", "--server",   address,
                                   "--robot",        robot,   "--udp-base", std::to_string(settings.udp_base),
                                   "--shared-clock", "-q"};
  if (namespace_name.empty()) Exec(self, args);
  args.insert(args.end(), {"--udp-subnet", subnet});
  args[0] = self;  // ip runs the program itself: its path, not a name, comes first
  args.insert(args.begin(), {"ip", "netns", "exec", namespace_name});
  Exec("ip", args);
}

// The user's program, in the robot's namespace when it has one.
pid_t StartProgram(const std::vector<std::string>& command, const std::string& namespace_name) {
  const pid_t program = ::fork();
  if (program != 0) return program;
  if (namespace_name.empty()) Exec(command.front(), command);
  std::vector<std::string> args = {"ip", "netns", "exec", namespace_name};
  args.insert(args.end(), command.begin(), command.end());
  Exec("ip", args);
}

void ReportProgram(const std::string& program, int status) {
  if (WIFEXITED(status))
    std::printf("  program %s exited with status %d%s\n", program.c_str(), WEXITSTATUS(status),
                WEXITSTATUS(status) == 127 ? " (could not be started)" : "");
  else if (WIFSIGNALED(status))
    std::printf("  program %s was stopped by signal %d%s\n", program.c_str(), WTERMSIG(status),
                WTERMSIG(status) == SIGTERM ? " at the end of the run" : "");
}

// Waits for the server's run to end; Ctrl-C asks it to end the run and write its results.
int WaitForServer(pid_t server) {
  int status = 0;
  bool forwarded = false;
  while (::waitpid(server, &status, WNOHANG) == 0) {
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

}  // namespace

int Launch(const sim::RunSpec& spec, const LaunchSettings& settings) {
  const std::vector<NodeId> robots = RobotsWithControllers(spec);
  const std::optional<NodeId> exec_robot = ExecRobot(spec, settings, robots);
  const std::unique_ptr<NetworkNamespaces> namespaces = MakeNamespaces(settings.loop, robots);
  const std::string bind = namespaces ? NetworkNamespaces::ServerAddress() : "127.0.0.1";
  const std::string self = std::filesystem::read_symlink("/proc/self/exe");
  std::signal(SIGINT, [](int) { g_interrupted = 1; });
  std::signal(SIGTERM, [](int) { g_interrupted = 1; });
  std::vector<std::string> taps;
  if (SimulatedRadio(settings.loop))
    for (NodeId id : robots) taps.push_back(spec.nodes[id].name + "=" + namespaces->Namespace(id));
  const auto [server, address] = StartServer(self, settings, bind, taps);
  const std::string subnet = SimulatedRadio(settings.loop) ? kRadioSubnet : NetworkNamespaces::Subnet();
  std::vector<pid_t> children;
  for (NodeId id : robots) {
    const std::string& name = spec.nodes[id].name;
    const std::string where = namespaces ? namespaces->Namespace(id) : "";
    children.push_back(StartAgent(self, settings, name, address, where, subnet));
    std::printf("  agent %s: process %d%s\n", name.c_str(), children.back(),
                where.empty() ? "" : (" in namespace " + where).c_str());
  }
  if (exec_robot) {
    const std::string where = namespaces ? namespaces->Namespace(*exec_robot) : "";
    children.push_back(StartProgram(settings.exec_command, where));
    std::printf("  program %s: process %d%s\n", settings.exec_command.front().c_str(), children.back(),
                where.empty() ? "" : (" in namespace " + where).c_str());
  }
  std::fflush(stdout);
  const int status = WaitForServer(server);
  for (pid_t a : children) ::kill(a, SIGTERM);
  for (pid_t a : children) {
    int ended = 0;
    ::waitpid(a, &ended, 0);
    if (exec_robot && a == children.back()) ReportProgram(settings.exec_command.front(), ended);
  }
  SayHowTheRunEnded(settings.output);
  std::printf("  results in %s/\n", settings.output.c_str());
  return status;
}

}  // namespace sanet::hil
