#include "agent_command.h"

#include <memory>
#include <stdexcept>

#include "ros2_agent_options.h"
#include "scenario/effective_scenario.h"
#include "scenario/scenario_loader.h"
#include "usarsim_agent/agent.h"
#include "usarsim_agent/server_link.h"
#include "wire/plugin_identity.h"

namespace sanet::cli {
namespace {

struct AgentArgs {
  std::string file, robot, server, subnet, peer_address, peer_interface, library;
  std::optional<int> udp_base;
  bool shared_clock = false, quiet = false;
  Ros2AgentArgs ros2;
  double test_clock_offset = 0;
  int test_protocol = wire::kSanetProtocol;
};

std::unique_ptr<usarsim_agent::ServerLink> Connect(const std::string& server) {
  const auto colon = server.rfind(':');
  const std::string port = colon == std::string::npos ? "" : server.substr(colon + 1);
  if (colon == 0 || port.empty() || port.size() > 5 || port.find_first_not_of("0123456789") != std::string::npos ||
      std::stoi(port) < 1 || std::stoi(port) > 65535)
    throw CLI::ValidationError("--server",
                               "expected HOST:PORT (a host name or IPv4 address and a port), not '" + server + "'");
  try {
    return std::make_unique<usarsim_agent::ServerLink>(server.substr(0, colon),
                                                       static_cast<std::uint16_t>(std::stoi(port)));
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).rfind("cannot find the server's host", 0) == 0)
      throw CLI::ValidationError("--server", e.what());
    throw;
  }
}

// The scenario: this computer's copy (which must be the server's), or the server's own.
scenario::Scenario ScenarioOf(const AgentArgs& a, usarsim_agent::ServerLink& link) {
  std::optional<scenario::Scenario> own;
  if (!a.file.empty()) own = scenario::LoadScenario(a.file);
  const usarsim_agent::ServerHello hello =
      link.Handshake(a.test_protocol, own ? scenario::ScenarioFingerprint(*own) : "");
  scenario::Scenario sc =
      own ? std::move(*own)
          : scenario::LoadScenarioText(link.FetchScenario(), "the scenario of the server at " + link.address());
  if (!a.quiet)
    std::printf("sanet agent %s: server %s (sanet %s), scenario %s %s (fingerprint %s)\n", a.robot.c_str(),
                link.address().c_str(), hello.version.c_str(), sc.run.name.c_str(),
                own ? ("from " + a.file).c_str() : "fetched", hello.fingerprint.c_str());
  return sc;
}

NodeId RobotOf(const scenario::Scenario& sc, const std::string& robot) {
  std::string robots;
  for (NodeId i = 0; i < sc.run.nodes.size(); ++i) {
    if (!sim::RunsAsAgent(sc.run.nodes[i])) continue;
    if (sc.run.nodes[i].name == robot) return i;
    robots += (robots.empty() ? "" : ", ") + sc.run.nodes[i].name;
  }
  throw CLI::ValidationError("--robot", "'" + robot + "' is not a robot with a controller in " + sc.file +
                                            " (those are: " + (robots.empty() ? "none" : robots) + ")");
}

usarsim_agent::PeerSettings PeerSettingsOf(const AgentArgs& a, const scenario::Scenario& sc) {
  usarsim_agent::PeerSettings peer;
  peer.udp_base_port = static_cast<std::uint16_t>(a.udp_base.value_or(sc.loop.udp_port));
  peer.udp_subnet = a.subnet;
  peer.peer_address = a.peer_address;
  peer.peer_interface = a.peer_interface;
  peer.peers = sc.loop.peers;
  return peer;
}

// --ros2: no server; the team from the scenario file, the robot from its ROS 2 topics.
int Ros2Agent(const AgentArgs& a, hosting::Registry& registry) {
  if (a.file.empty())
    throw CLI::ValidationError("--scenario", "--ros2 runs without a server: give the team's scenario file");
  if (!a.server.empty())
    throw CLI::ValidationError("--server",
                               "--ros2 runs without a server: the robot's topics are its sensors and "
                               "motors; drop --server (or --ros2)");
  scenario::Scenario sc = scenario::LoadScenario(a.file);
  const NodeId id = RobotOf(sc, a.robot);
  sim::ControllerSpec& controller = *sc.run.nodes[id].controller;
  if (!a.library.empty()) controller.library = a.library;
  return StartRos2Agent(sc, id, a.ros2, PeerSettingsOf(a, sc), a.quiet, registry);
}

int Agent(const AgentArgs& a, hosting::Registry& registry) {
  if (a.ros2.on) return Ros2Agent(a, registry);
  std::unique_ptr<usarsim_agent::ServerLink> link = Connect(a.server.empty() ? "127.0.0.1:3000" : a.server);
  scenario::Scenario sc = ScenarioOf(a, *link);
  const NodeId id = RobotOf(sc, a.robot);
  sim::ControllerSpec& controller = *sc.run.nodes[id].controller;
  if (!a.library.empty()) controller.library = a.library;
  const std::string differs = wire::PluginDifference(link->FetchPlugin(a.robot), wire::IdentifyPlugin(controller));
  if (!differs.empty()) throw std::runtime_error("this robot's controller is not the server's: " + differs);
  usarsim_agent::AgentSettings settings;
  settings.peer = PeerSettingsOf(a, sc);
  settings.shared_clock = a.shared_clock;
  settings.clock_skew = a.test_clock_offset;
  settings.time_port = link->time_port();
  settings.quiet = a.quiet;
  return usarsim_agent::RunAgent(sc.run, id, settings, std::move(link), registry);
}

}  // namespace

Command AddAgent(CLI::App& app) {
  auto a = std::make_shared<AgentArgs>();
  CLI::App* cmd = app.add_subcommand("agent",
                                     "Run one robot's controller as its own process, on this computer or another: "
                                     "sensors and motors through a `sanet serve` server, messages over real UDP "
                                     "(docs/remote-robots.md)");
  cmd->add_option("--server", a->server,
                  "The server, HOST:PORT (a host name or an IPv4 address; default 127.0.0.1:3000)");
  cmd->add_option("--robot", a->robot, "The robot to drive (its name in the scenario)")->required();
  cmd->add_option("--scenario", a->file,
                  "This computer's copy of the scenario, which must be the server's (same fingerprint); without "
                  "it the agent fetches the server's");
  AddPythonPath(cmd);
  cmd->add_option("--library", a->library,
                  "Where this computer keeps the robot's controller library (default: the scenario's path); it "
                  "must be the server's build (same SHA-256)");
  cmd->add_option("--peer-address", a->peer_address,
                  "The address this robot's agent listens on for the other agents (overrides the scenario's "
                  "loop.peers)");
  cmd->add_option("--peer-interface", a->peer_interface,
                  "The interface (e.g. wlan0) robot-to-robot datagrams use: the peer socket is bound to it and "
                  "takes its address unless --peer-address is given (Linux before 5.7: needs root or CAP_NET_RAW)");
  cmd->add_option("--udp-base", a->udp_base,
                  "UDP port of node 0; node i uses base + i (default: the scenario's loop.udp_port, 47000)")
      ->check(CLI::Range(1024, 60000));
  cmd->add_option("--udp-subnet", a->subnet,
                  "Instead: node i listens on SUBNET.(i+1) at the base port (agents in network namespaces)");
  cmd->add_flag("-q,--quiet", a->quiet, "Print only errors (and warnings)");
  cmd->add_flag("--shared-clock", a->shared_clock,
                "The server runs on this machine: take its clock exactly instead of estimating it");
  cmd->add_option("--test-clock-offset", a->test_clock_offset,
                  "For tests: add this many seconds to this computer's clock (the estimate must find it)")
      ->group("");  // for tests: not in --help
  cmd->add_option("--test-protocol-version", a->test_protocol,
                  "For tests: claim this version of sanet's protocol (the server must refuse another)")
      ->check(CLI::Range(1, 1000000))
      ->group("");  // for tests: not in --help
  AddRos2AgentOptions(cmd, a->ros2);
  return {cmd, [a](hosting::Registry& r) { return Agent(*a, r); }};
}

}  // namespace sanet::cli
