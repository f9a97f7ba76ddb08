#include "sim/robot_messages.h"

#include <cmath>
#include <limits>

namespace sanet::sim {
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

namespace {

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

// The world-frame velocity the driver reports, in the body's frame.
Twist2D InBody(const Twist2D& world, double theta) {
  const Vec2 v = Rotate({world.vx, world.vy}, -theta);
  return {v.x, v.y, world.omega};
}

void AddSensorMounts(msg::tf2_msgs::TFMessage& out, const robots::ModelSpec& model, const RobotFrames& frames,
                     double t) {
  if (const auto& laser = model.sensors.laser)
    out.transforms.push_back(Transform(frames.base, frames.laser, t, laser->mount_x, 0, laser->mount_height, 0));
  if (const auto& ir = model.sensors.ir)
    for (std::size_t i = 0; i < ir->angles.size(); ++i) {
      const double a = ir->angles[i];
      out.transforms.push_back(Transform(frames.base, frames.ir[i], t, ir->mount_x + ir->mount_radius * std::cos(a),
                                         ir->mount_radius * std::sin(a), ir->mount_height, a));
    }
}

}  // namespace

RobotFrames FramesOf(const std::string& robot, const robots::ModelSpec& model) {
  RobotFrames f{robot + "/odom", robot + "/base_link", robot + "/laser", {}};
  if (model.sensors.ir)
    for (std::size_t i = 0; i < model.sensors.ir->angles.size(); ++i)
      f.ir.push_back(robot + "/ir_" + std::to_string(i));
  return f;
}

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

msg::nav_msgs::Odometry OdometryOf(const SensorReadings& r, const Pose2D& start, const RobotFrames& frames) {
  const Pose2D pose = Relative(start, r.odometry.value_or(start));
  return OdometryIn(frames.odom, frames.base, r.time, pose, InBody(r.velocity, r.ground_truth.theta));
}

msg::nav_msgs::Odometry GroundTruthOf(const SensorReadings& r, const RobotFrames& frames) {
  return OdometryIn("world", frames.base, r.time, r.ground_truth, InBody(r.velocity, r.ground_truth.theta));
}

namespace {

// REP 117: a beam that returns nothing within the sensor's range reads +Inf, not its maximum
// (which a consumer would take for an obstacle there). sanet's sensors read their maximum when
// nothing is nearer, and noise is clamped to it, so a reading at the maximum is "nothing seen".
float NothingSeenAsInfinity(double range, double max_range) {
  return range >= max_range ? std::numeric_limits<float>::infinity() : static_cast<float>(range);
}

}  // namespace

msg::sensor_msgs::LaserScan ScanOf(const RangeScan& scan, double t, const std::string& frame) {
  msg::sensor_msgs::LaserScan s;
  s.header.stamp = StampOf(t);
  s.header.frame_id = frame;
  if (!scan.angles.empty()) {
    s.angle_min = static_cast<float>(scan.angles.front());
    s.angle_max = static_cast<float>(scan.angles.back());
    if (scan.angles.size() > 1)
      s.angle_increment = static_cast<float>((scan.angles.back() - scan.angles.front()) / (scan.angles.size() - 1));
  }
  s.range_min = 0;
  s.range_max = static_cast<float>(scan.max_range);
  s.ranges.reserve(scan.ranges.size());
  for (double range : scan.ranges) s.ranges.push_back(NothingSeenAsInfinity(range, scan.max_range));
  return s;
}

msg::sensor_msgs::Range RangeOf(const RangeScan& ir, std::size_t i, double t, const std::string& frame, double noise) {
  msg::sensor_msgs::Range r;
  r.header.stamp = StampOf(t);
  r.header.frame_id = frame;
  r.radiation_type = msg::sensor_msgs::Range::INFRARED;
  r.field_of_view = 0;
  r.min_range = 0;
  r.max_range = static_cast<float>(ir.max_range);
  r.range = NothingSeenAsInfinity(ir.ranges.at(i), ir.max_range);
  r.variance = static_cast<float>(noise * noise);
  return r;
}

msg::geometry_msgs::TransformStamped OdomToBase(const SensorReadings& r, const Pose2D& start,
                                                const RobotFrames& frames) {
  const Pose2D pose = Relative(start, r.odometry.value_or(start));
  return Transform(frames.odom, frames.base, r.time, pose.x, pose.y, 0, pose.theta);
}

msg::tf2_msgs::TFMessage StaticTransforms(std::size_t count, const std::function<const NodeSpec&(NodeId)>& spec_of,
                                          const std::map<NodeId, RobotFrames>& frames, double t) {
  msg::tf2_msgs::TFMessage out;
  for (NodeId id = 0; id < count; ++id) {
    const NodeSpec& node = spec_of(id);
    const Pose2D& p = node.pose;
    if (node.model.kind == robots::ModelKind::kMote) {
      out.transforms.push_back(Transform("world", node.name, t, p.x, p.y, 0, p.theta));
      continue;
    }
    const auto given = frames.find(id);
    const RobotFrames robot = given != frames.end() ? given->second : FramesOf(node.name, node.model);
    out.transforms.push_back(Transform("world", robot.odom, t, p.x, p.y, 0, p.theta));
    AddSensorMounts(out, node.model, robot, t);
  }
  return out;
}

}  // namespace sanet::sim
