#include "ros2_presentation/urdf_frames.h"

#include <cmath>

namespace sanet::ros2_presentation {
namespace {

using Quaternion = std::array<double, 4>;  // x, y, z, w

Quaternion Multiply(const Quaternion& a, const Quaternion& b) {
  return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1], a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3], a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}

// A turn of `angle` rad about `axis` (normalised here: URDF does not require a unit axis).
Quaternion AboutAxis(const std::array<double, 3>& axis, double angle) {
  const double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  if (norm == 0) return {0, 0, 0, 1};
  const double s = std::sin(angle / 2) / norm;
  return {axis[0] * s, axis[1] * s, axis[2] * s, std::cos(angle / 2)};
}

msg::geometry_msgs::TransformStamped Placed(const std::string& parent, const std::string& child, double t,
                                            const robots::UrdfPose& pose, const Quaternion& turn = {0, 0, 0, 1}) {
  msg::geometry_msgs::TransformStamped tf;
  tf.header.stamp = StampOf(t);
  tf.header.frame_id = parent;
  tf.child_frame_id = child;
  tf.transform.translation.x = pose.xyz[0];
  tf.transform.translation.y = pose.xyz[1];
  tf.transform.translation.z = pose.xyz[2];
  const Quaternion q = Multiply(pose.xyzw, turn);
  tf.transform.rotation.x = q[0], tf.transform.rotation.y = q[1], tf.transform.rotation.z = q[2];
  tf.transform.rotation.w = q[3];
  return tf;
}

// The index of `joint` among the wheels, or -1.
int WheelIndex(const robots::UrdfSource& urdf, const std::string& joint) {
  for (std::size_t i = 0; i < urdf.wheels.size(); ++i)
    if (urdf.wheels[i] == joint) return static_cast<int>(i);
  return -1;
}

}  // namespace

std::string UrdfLinkFrame(const RobotFrames& frames, const std::string& link) {
  return frames.prefix + "/urdf/" + link;
}

void UrdfStaticTransforms(const robots::UrdfSource& urdf, const RobotFrames& frames, double t,
                          std::vector<msg::geometry_msgs::TransformStamped>& out) {
  out.push_back(Placed(frames.base, UrdfLinkFrame(frames, urdf.root), t, urdf.root_pose));
  for (const robots::UrdfJoint& j : urdf.joints)
    if (WheelIndex(urdf, j.name) < 0)
      out.push_back(Placed(UrdfLinkFrame(frames, j.parent), UrdfLinkFrame(frames, j.child), t, j.origin));
}

msg::tf2_msgs::TFMessage UrdfWheelTransforms(const robots::UrdfSource& urdf, const RobotFrames& frames, double t,
                                             const std::array<double, 3>& angles) {
  msg::tf2_msgs::TFMessage tf;
  for (const robots::UrdfJoint& j : urdf.joints) {
    const int wheel = WheelIndex(urdf, j.name);
    if (wheel < 0 || wheel >= static_cast<int>(angles.size())) continue;
    const double angle = angles[static_cast<std::size_t>(wheel)] * urdf.wheel_signs.at(static_cast<std::size_t>(wheel));
    tf.transforms.push_back(
        Placed(UrdfLinkFrame(frames, j.parent), UrdfLinkFrame(frames, j.child), t, j.origin, AboutAxis(j.axis, angle)));
  }
  return tf;
}

}  // namespace sanet::ros2_presentation
