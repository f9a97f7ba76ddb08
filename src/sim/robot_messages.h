// A robot's readings as the ROS 2 messages a ROS 2 robot publishes (REP 103 axes: x forward,
// y left, z up, angles counter-clockwise, as sanet's; REP 105 frames): pure functions of what
// the robot's owner read, so that the face, the run's log and a stream publish the same.
//
// Frames, per robot R: R/odom (fixed in the world at R's start pose, the origin of its
// odometry), R/base_link (the body), R/laser and R/ir_<i> (the sensors where they are mounted);
// world for ground truth, motes and the start poses.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "ros2msg/messages.h"
#include "sim/driver.h"

namespace sanet::sim {

namespace msg = ros2msg;

struct RobotFrames {
  std::string odom, base, laser;
  std::vector<std::string> ir;
};
RobotFrames FramesOf(const std::string& robot, const robots::ModelSpec& model);

msg::builtin_interfaces::Time StampOf(double t);             // s of simulated time
msg::geometry_msgs::Quaternion YawQuaternion(double theta);  // a turn of `theta` rad about z

// Wheel odometry in R/odom (relative to the start pose), with the body's velocity in R/base_link.
msg::nav_msgs::Odometry OdometryOf(const SensorReadings& r, const Pose2D& start, const RobotFrames& frames);
// The true pose in world, child R/base_link.
msg::nav_msgs::Odometry GroundTruthOf(const SensorReadings& r, const RobotFrames& frames);
msg::sensor_msgs::LaserScan ScanOf(const RangeScan& scan, double t, const std::string& frame);
// IR sensor `i`: one ray (field of view 0), its noise's variance.
msg::sensor_msgs::Range RangeOf(const RangeScan& ir, std::size_t i, double t, const std::string& frame, double noise);

// R/odom -> R/base_link now.
msg::geometry_msgs::TransformStamped OdomToBase(const SensorReadings& r, const Pose2D& start,
                                                const RobotFrames& frames);
// What does not move: world -> R/odom (the start pose) and R/base_link -> each sensor, for every
// robot (`frames`: each robot's, by node; FramesOf for the others); world -> M for every mote, of
// the `count` nodes whose specs `spec_of` gives, stamped `t`.
msg::tf2_msgs::TFMessage StaticTransforms(std::size_t count, const std::function<const NodeSpec&(NodeId)>& spec_of,
                                          const std::map<NodeId, RobotFrames>& frames, double t = 0);
// `parent` -> `child` at time `t`: a shift by (x, y, z) and a turn of `yaw` about z.
msg::geometry_msgs::TransformStamped Transform(const std::string& parent, const std::string& child, double t, double x,
                                               double y, double z, double yaw);

// `pose` seen from `origin`: both in the same frame.
Pose2D Relative(const Pose2D& origin, const Pose2D& pose);

}  // namespace sanet::sim
