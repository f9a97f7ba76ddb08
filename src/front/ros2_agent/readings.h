// A ROS 2 robot's messages as a controller's Node gives them (REP 103 axes, as sanet's): pure
// functions, so that what an agent reads is tested without DDS.
#pragma once

#include "ros2msg/messages.h"
#include "sanet/node.h"

namespace sanet::ros2_agent {

namespace msg = ros2msg;

double Seconds(const msg::builtin_interfaces::Time& t);
msg::builtin_interfaces::Time StampAt(double seconds);
// x, y and the yaw of a pose (its orientation's rotation about z).
Pose2D PoseOf(const msg::geometry_msgs::Pose& pose);
// `relative` (in the frame of odometry, which starts at the robot's start pose) in the world.
Pose2D InWorld(const Pose2D& start, const Pose2D& relative);
// A laser scan, each beam at angle_min + i angle_increment; a range that is no number, infinite
// or beyond range_max (nothing seen, as ROS 2 drivers say it) becomes range_max.
RangeScan ScanOf(const msg::sensor_msgs::LaserScan& scan);
// One range, as ScanOf reads a beam.
double RangeOf(const msg::sensor_msgs::Range& range);
msg::geometry_msgs::Twist TwistOf(const Twist2D& v);

}  // namespace sanet::ros2_agent
