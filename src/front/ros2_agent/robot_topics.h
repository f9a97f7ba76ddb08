// What a ROS 2 robot's topics are called, typed and how they are read: by default those of
// sanet's ROS 2 face (docs/ros2.md), so that an agent finds a served robot as it is; robots
// differ (a TurtleBot's, a Pioneer driver's, motion capture), so a small per-robot YAML file and
// the command line (--ros2-remap KEY=TOPIC) rename and retype them (docs/ros2-robots.md).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ros2_face/dds_domain.h"

namespace sanet::ros2_agent {

using ros2_face::Qos;

// One topic: its ROS name (relative names are under the robot's namespace) and how it is read.
struct Topic {
  std::string name;
  Qos qos;
};

enum class CmdVelType { kTwist, kTwistStamped };
enum class GroundTruthType { kNone, kOdometry, kPoseStamped };

struct RobotTopics {
  std::string ns;                        // the robot's namespace, "/scout"; "" for none
  Topic odom{"odom", Qos::kSensorData};  // nav_msgs/Odometry, relative to the robot's start pose
  Topic scan{"scan", Qos::kSensorData};  // sensor_msgs/LaserScan
  std::vector<Topic> ir;                 // sensor_msgs/Range, one per IR sensor of the robot's model
  Topic ground_truth{"ground_truth", Qos::kSensorData};
  GroundTruthType ground_truth_type = GroundTruthType::kOdometry;
  Topic cmd_vel{"cmd_vel", Qos::kDefault};
  CmdVelType cmd_vel_type = CmdVelType::kTwist;
  Topic clock{"/clock", Qos::kClock};  // rosgraph_msgs/Clock, read with use_sim_time
  bool use_sim_time = false;           // Now() from /clock, not from this computer's clock
  double odom_timeout = 0.5;           // s without odom after which the robot is stopped
};

// The face's topics for robot `name` with `ir_count` IR sensors: /name/odom, /name/ir_0, ...
RobotTopics DefaultTopics(const std::string& name, std::size_t ir_count);

// Applies a per-robot file (docs/ros2-robots.md) over `topics`. Throws scenario::ScenarioError
// naming the file, line and field.
void ReadRobotFile(const std::string& path, RobotTopics& topics);

// KEY=TOPIC from the command line: KEY is odom, scan, ground_truth, cmd_vel, clock or ir_I; TOPIC
// a ROS name, or "none" for ground_truth. Throws std::invalid_argument saying what is wrong.
void Remap(const std::string& assignment, RobotTopics& topics);

// The topic's full ROS name: relative names under the namespace.
std::string FullName(const RobotTopics& topics, const Topic& topic);

}  // namespace sanet::ros2_agent
