#include "ros2_agent_options.h"

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "interruption.h"
#include "ros2_agent/ros2_agent.h"
#include "ros2_options.h"
#include "scenario/effective_scenario.h"
#include "scenario/yaml_reader.h"
#include "sensors/range_fan.h"

namespace sanet::cli {
namespace {

constexpr const char* kKeyHow = " (64 hex digits, the same for the whole team; make one with: openssl rand -hex 32)";

// The team's datagram key: --key-file, else SANET_TEAM_KEY.
wire::DatagramKey TeamKey(const Ros2AgentArgs& args) {
  std::string hex;
  if (!args.key_file.empty()) {
    std::ifstream in(args.key_file);
    if (!in) throw CLI::ValidationError("--key-file", "cannot read " + args.key_file + ": " + std::strerror(errno));
    in >> hex;
    if (const auto key = wire::DatagramKey::FromHex(hex)) return *key;
    throw CLI::ValidationError("--key-file", args.key_file + " holds no key" + kKeyHow);
  }
  const char* env = std::getenv("SANET_TEAM_KEY");
  if (!env || !*env)
    throw CLI::ValidationError("--key-file", std::string("--ros2 needs the team's key for the datagrams between "
                                                         "robots: --key-file FILE or SANET_TEAM_KEY") +
                                                 kKeyHow);
  if (const auto key = wire::DatagramKey::FromHex(env)) return *key;
  throw CLI::ValidationError("SANET_TEAM_KEY", std::string("holds no key") + kKeyHow);
}

ros2_agent::RobotTopics TopicsOf(const sim::NodeSpec& node, const Ros2AgentArgs& args) {
  const auto& ir = sensors::DefaultFan(node.model, "ir");
  ros2_agent::RobotTopics topics = ros2_agent::DefaultTopics(node.name, ir ? ir->angles.size() : 0);
  if (!args.robot_file.empty()) ros2_agent::ReadRobotFile(args.robot_file, topics);
  for (const std::string& remap : args.remaps) try {
      ros2_agent::Remap(remap, topics);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("--ros2-remap", e.what());
    }
  if (args.use_sim_time) topics.use_sim_time = true;
  if (args.stamped) topics.cmd_vel_type = ros2_agent::CmdVelType::kTwistStamped;
  return topics;
}

// --start-at: a Unix time in seconds, within a day of now (milliseconds, or a day's mistake, are
// refused); not with /clock, whose time 0 is the simulator's.
void CheckStartAt(const Ros2AgentArgs& args, const ros2_agent::RobotTopics& topics) {
  if (!args.start_at) return;
  if (topics.use_sim_time)
    throw CLI::ValidationError("--start-at",
                               "with --use-sim-time (or use_sim_time in the robot's file) time 0 is "
                               "/clock's: the team's start is the simulator's, drop --start-at");
  const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  if (*args.start_at > now + 86400 || *args.start_at < now - 86400)
    throw CLI::ValidationError("--start-at",
                               std::to_string(*args.start_at) + " is " +
                                   std::to_string(static_cast<long long>(*args.start_at - now)) +
                                   " s from now: give Unix time in seconds, e.g. $(( $(date +%s) + 20 ))");
}

}  // namespace

void AddRos2AgentOptions(CLI::App* cmd, Ros2AgentArgs& args) {
  const char* group = "ROS 2 robot (--ros2)";
  cmd->add_flag("--ros2", args.on,
                "Drive a ROS 2 robot through its topics, with no server: the team from --scenario, messages between "
                "robots over UDP with the team's key (docs/ros2-robots.md)")
      ->group(group);
  cmd->add_option("--ros2-domain", args.domain,
                  "DDS domain of the robot (default: the scenario's ros2.domain, else ROS_DOMAIN_ID, else 0)")
      ->check(CLI::Range(0, 232))
      ->group(group);
  cmd->add_option("--ros2-interface", args.interface, "The network interface (name or IPv4 address) of the robot's DDS")
      ->group(group);
  cmd->add_option("--ros2-robot", args.robot_file,
                  "A YAML file naming and typing the robot's topics (namespace, odom, scan, ir, ground_truth, "
                  "cmd_vel, clock, use_sim_time, odom_timeout); the defaults are the ROS 2 face's")
      ->check(CLI::ExistingFile)
      ->group(group);
  cmd->add_option("--ros2-remap", args.remaps, "KEY=TOPIC: odom, scan, ground_truth (or none), cmd_vel, clock, ir_I")
      ->group(group);
  cmd->add_flag("--use-sim-time", args.use_sim_time, "Now() from /clock (a simulator's), not from this computer")
      ->group(group);
  cmd->add_flag("--ros2-cmd-vel-stamped", args.stamped, "Publish cmd_vel as geometry_msgs/TwistStamped")->group(group);
  cmd->add_option("--key-file", args.key_file,
                  "The team's datagram key (64 hex digits); default: the environment's SANET_TEAM_KEY")
      ->group(group);
  cmd->add_option("-o,--output", args.output, "The agent's results folder (default: results/SCENARIO-ROBOT)")
      ->group(group);
  cmd->add_flag("--force", args.force, "Write into a folder that holds files no sanet agent wrote")->group(group);
  cmd->add_option("--start-at", args.start_at,
                  "The team's time 0 as Unix time (s): every agent given the same value starts then and agrees on "
                  "Now() as far as the computers' clocks do (NTP, PTP); default: when this agent starts")
      ->group(group);
  cmd->add_option("--duration", args.duration,
                  "s of the robot's clock after which the agent ends (default: the "
                  "scenario's duration)")
      ->check(CLI::PositiveNumber)
      ->group(group);
}

int StartRos2Agent(const scenario::Scenario& sc, NodeId id, const Ros2AgentArgs& args, usarsim_agent::PeerSettings peer,
                   bool quiet, hosting::Registry& registry) {
  ros2_agent::Ros2AgentSettings settings;
  settings.robot.domain = static_cast<std::uint32_t>(Ros2Domain(args.domain, sc.ros2 ? sc.ros2->domain : -1));
  settings.robot.interface = args.interface;
  settings.robot.topics = TopicsOf(sc.run.nodes[id], args);
  CheckStartAt(args, settings.robot.topics);
  settings.scenario_fingerprint = scenario::ScenarioFingerprint(sc);
  settings.robot.model = sc.run.nodes[id].model;
  settings.robot.start = sc.run.nodes[id].pose;
  settings.peer = std::move(peer);
  settings.key = TeamKey(args);
  settings.output = args.output.empty() ? "results/" + sc.run.name + "-" + sc.run.nodes[id].name : args.output;
  settings.force = args.force;
  settings.start_at = args.start_at;
  settings.quiet = quiet;
  InstallStopHandlers();
  settings.stop_requested = [] { return InterruptSignal() != 0; };
  sim::RunSpec spec = sc.run;
  if (args.duration) spec.duration = *args.duration;
  return ros2_agent::RunRos2Agent(spec, id, settings, registry);
}

}  // namespace sanet::cli
