// `sanet agent --ros2`: the options of an agent on a ROS 2 robot, and its start.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hosting/controller_registry.h"
#include "scenario/scenario_loader.h"
#include "usarsim_agent/peer_socket.h"

namespace sanet::cli {

struct Ros2AgentArgs {
  bool on = false;                  // --ros2
  std::optional<int> domain;        // default: the scenario's ros2.domain, else ROS_DOMAIN_ID, else 0
  std::string interface;            // --ros2-interface
  std::string robot_file;           // --ros2-robot FILE: the robot's topics
  std::vector<std::string> remaps;  // --ros2-remap KEY=TOPIC
  bool use_sim_time = false, stamped = false;
  std::string key_file;  // --key-file; else SANET_TEAM_KEY
  std::string output;    // -o; default results/<scenario>-<robot>
  bool force = false;
  std::optional<double> start_at;  // --start-at UNIX_TIME
  std::optional<double> duration;  // over the scenario's
};

void AddRos2AgentOptions(CLI::App* cmd, Ros2AgentArgs& args);
// Runs robot `id`'s controller against its ROS 2 topics (no server). Returns the exit code.
int StartRos2Agent(const scenario::Scenario& sc, NodeId id, const Ros2AgentArgs& args, usarsim_agent::PeerSettings peer,
                   bool quiet, hosting::Registry& registry);

}  // namespace sanet::cli
