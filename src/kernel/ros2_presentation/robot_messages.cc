#include "ros2_presentation/robot_messages.h"

#include <cmath>

#include "ros2_presentation/sensor_messages.h"
#include "ros2_presentation/urdf_frames.h"

namespace sanet::ros2_presentation {

msg::geometry_msgs::Quaternion YawQuaternion(double theta) {
  msg::geometry_msgs::Quaternion q;
  q.z = std::sin(theta / 2);
  q.w = std::cos(theta / 2);
  return q;
}

msg::geometry_msgs::TransformStamped Transform(const std::string& parent, const std::string& child, double t, double x,
                                               double y, double z, double yaw) {
  msg::geometry_msgs::TransformStamped tf;
  tf.header.stamp = StampOf(t);
  tf.header.frame_id = parent;
  tf.child_frame_id = child;
  tf.transform.translation.x = x;
  tf.transform.translation.y = y;
  tf.transform.translation.z = z;
  tf.transform.rotation = YawQuaternion(yaw);
  return tf;
}

msg::nav_msgs::Odometry OdometryIn(const std::string& frame, const std::string& child, double t, const Pose2D& pose,
                                   const Twist2D& body_velocity) {
  msg::nav_msgs::Odometry o;
  o.header.stamp = StampOf(t);
  o.header.frame_id = frame;
  o.child_frame_id = child;
  o.pose.pose.position.x = pose.x;
  o.pose.pose.position.y = pose.y;
  o.pose.pose.orientation = YawQuaternion(pose.theta);
  o.twist.twist.linear.x = body_velocity.vx;
  o.twist.twist.linear.y = body_velocity.vy;
  o.twist.twist.angular.z = body_velocity.omega;
  return o;
}

Twist2D InBody(const Twist2D& world, double theta) {
  const Vec2 v = Rotate({world.vx, world.vy}, -theta);
  return {v.x, v.y, world.omega};
}

RobotFrames FramesOf(const std::string& robot) { return {robot, robot + "/odom", robot + "/base_link"}; }

msg::builtin_interfaces::Time StampOf(double t) {
  msg::builtin_interfaces::Time stamp;
  const double whole = std::floor(t);
  stamp.sec = static_cast<std::int32_t>(whole);
  stamp.nanosec = static_cast<std::uint32_t>(std::llround((t - whole) * 1e9) % 1000000000);
  return stamp;
}

Pose2D Relative(const Pose2D& origin, const Pose2D& pose) {
  const Vec2 d = Rotate({pose.x - origin.x, pose.y - origin.y}, -origin.theta);
  return {d.x, d.y, std::remainder(pose.theta - origin.theta, 2 * M_PI)};
}

msg::geometry_msgs::TransformStamped OdomToBase(double t, const std::optional<Pose2D>& odometry, const Pose2D& start,
                                                const RobotFrames& frames) {
  const Pose2D pose = Relative(start, odometry.value_or(start));
  return Transform(frames.odom, frames.base, t, pose.x, pose.y, 0, pose.theta);
}

msg::tf2_msgs::TFMessage StaticTransforms(std::size_t count, const std::function<const sim::NodeSpec&(NodeId)>& spec_of,
                                          const std::map<NodeId, RobotFrames>& frames, double t) {
  msg::tf2_msgs::TFMessage out;
  for (NodeId id = 0; id < count; ++id) {
    const sim::NodeSpec& node = spec_of(id);
    const Pose2D& p = node.pose;
    if (!robots::HasDrive(node.model)) {
      out.transforms.push_back(Transform("world", node.name, t, p.x, p.y, 0, p.theta));
      continue;
    }
    const auto given = frames.find(id);
    const RobotFrames robot = given != frames.end() ? given->second : FramesOf(node.name);
    out.transforms.push_back(Transform("world", robot.odom, t, p.x, p.y, 0, p.theta));
    for (const auto& [instance, config] : sensors::PresentationOrder(node.model))
      if (const SensorMessages* kind = MessagesOf(config->kind))
        kind->Mounts(instance, config->settings, robot, t, out.transforms);
    if (node.model.urdf) UrdfStaticTransforms(*node.model.urdf, robot, t, out.transforms);
  }
  return out;
}

}  // namespace sanet::ros2_presentation
