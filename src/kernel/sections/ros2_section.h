// The scenario's `ros2` section: `sanet serve` makes the world's robots ROS 2 robots over DDS
// (docs/ros2.md), with these names and rates. A front-end section: the scenario layer reads it,
// the ROS 2 face applies it, the simulation never sees it.
#pragma once

#include <string>
#include <vector>

namespace sanet::sections {

enum class CmdVelType { kTwist, kTwistStamped };
// The ROS 2 release whose graph messages the face speaks: rmw_dds_common's Gid, in the
// ros_discovery_info that `ros2 node list` reads, is 24 bytes in Humble and 16 from Iron on.
enum class Ros2Distro { kHumble, kJazzy };

// One robot's topics: under /<namespace>/ (its frames <namespace>/odom, ...), at `rate` Hz.
struct Ros2Robot {
  std::string robot;
  std::string ns;   // empty: the robot's name
  double rate = 0;  // Hz; 0: the section's
};

// A name ROS 2 takes for a namespace: parts of letters, digits and `_`, none starting with a
// digit, joined by single `/` (no leading or trailing one).
bool IsRosName(const std::string& name);

struct Ros2Spec {
  int domain = -1;   // DDS domain; -1: ROS_DOMAIN_ID, else 0
  double rate = 10;  // Hz of each robot's sensor messages
  CmdVelType cmd_vel = CmdVelType::kTwist;
  Ros2Distro distro = Ros2Distro::kJazzy;  // the newer: Iron's and Jazzy's ros_discovery_info
  double cmd_vel_timeout = 0.5;            // s without cmd_vel after which a robot the face drives stops; 0: never
  std::vector<Ros2Robot> robots;           // robots whose names or rates differ
};

}  // namespace sanet::sections
