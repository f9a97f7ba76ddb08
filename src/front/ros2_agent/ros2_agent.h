// `sanet agent --ros2`: one robot's controller plugin on a ROS 2 robot, with no simulator. The
// team (robots, controllers, parameters, peers' addresses) comes from the scenario file; the
// robot's readings and motion from its ROS 2 topics; the other robots' messages over UDP,
// authenticated with the team's key; the controller runs through the same host as in every mode
// (hosting::ControllerHost) on the step grid of the robot's clock. It stops the robot (zero
// cmd_vel) and says why when odometry stops coming, when the controller fails, and when it ends.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "hosting/controller_registry.h"
#include "ros2_agent/ros2_robot.h"
#include "sim/run_spec.h"
#include "usarsim_agent/peer_socket.h"
#include "wire/agent_datagram.h"

namespace sanet::ros2_agent {

struct Ros2AgentSettings {
  Ros2RobotSettings robot;
  usarsim_agent::PeerSettings peer;
  wire::DatagramKey key;  // the team's, for the datagrams between agents
  std::string output;     // the agent's results folder
  bool force = false;     // clear a folder of other files
  // The team's time 0, as Unix time (s), when the robot's clock is this computer's: the agents
  // of a team started with the same value agree on Now() as far as their clocks (NTP, PTP) do.
  // Without it, time 0 is when this agent started.
  std::optional<double> start_at;
  bool quiet = false;
  std::function<bool()> stop_requested;  // Ctrl-C: end with the results
  std::string scenario_fingerprint;      // in summary.json, so that sanet merge knows a team's folders
};

// Returns the exit code: 0 at the scenario's duration or when stopped, 1 when the controller failed.
int RunRos2Agent(const sim::RunSpec& spec, NodeId robot, const Ros2AgentSettings& settings,
                 hosting::Registry& registry);

}  // namespace sanet::ros2_agent
