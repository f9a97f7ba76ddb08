// What a robot's ROS 2 messages share, whichever sensor they carry (REP 103 axes: x forward, y
// left, z up, angles counter-clockwise, as sanet's; REP 105 frames): stamps, frames, transforms,
// odometry messages. Each sensor kind's own messages are its part (ros2_presentation/sensor_messages.h); these
// are pure functions of what the robot's owner read, so that the face, the run's log and a stream
// publish the same.
//
// Frames, per robot R: R/odom (fixed in the world at R's start pose, the origin of its
// odometry), R/base_link (the body), R/<sensor> where each sensor is mounted; world for ground
// truth, motes and the start poses.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ros2msg/messages.h"
#include "sim/run_spec.h"

namespace sanet::ros2_presentation {

namespace msg = ros2msg;

struct RobotFrames {
  std::string prefix;  // R: the robot's name or namespace
  std::string odom, base;
  // The frame of a sensor mounted as `name` ("laser", "ir_0", "laser_rear").
  std::string Sensor(const std::string& name) const { return prefix + "/" + name; }
};
RobotFrames FramesOf(const std::string& robot);

msg::builtin_interfaces::Time StampOf(double t);             // s of simulated time
msg::geometry_msgs::Quaternion YawQuaternion(double theta);  // a turn of `theta` rad about z

// A pose in `frame` with a velocity in the body's frame (`child`).
msg::nav_msgs::Odometry OdometryIn(const std::string& frame, const std::string& child, double t, const Pose2D& pose,
                                   const Twist2D& body_velocity);
// A world-frame velocity in the frame of a body heading `theta`.
Twist2D InBody(const Twist2D& world, double theta);

// R/odom -> R/base_link at `t`, from the odometry's pose (the start pose without one).
msg::geometry_msgs::TransformStamped OdomToBase(double t, const std::optional<Pose2D>& odometry, const Pose2D& start,
                                                const RobotFrames& frames);
// What does not move: world -> R/odom (the start pose) and R/base_link -> each sensor (and a URDF
// robot's links: ros2_presentation/urdf_frames.h), for every robot (`frames`: each robot's, by node; FramesOf for the
// others); world -> M for every mote, of the `count` nodes whose specs `spec_of` gives, stamped `t`.
msg::tf2_msgs::TFMessage StaticTransforms(std::size_t count, const std::function<const sim::NodeSpec&(NodeId)>& spec_of,
                                          const std::map<NodeId, RobotFrames>& frames, double t = 0);
// `parent` -> `child` at time `t`: a shift by (x, y, z) and a turn of `yaw` about z.
msg::geometry_msgs::TransformStamped Transform(const std::string& parent, const std::string& child, double t, double x,
                                               double y, double z, double yaw);

// `pose` seen from `origin`: both in the same frame.
Pose2D Relative(const Pose2D& origin, const Pose2D& pose);

}  // namespace sanet::ros2_presentation
