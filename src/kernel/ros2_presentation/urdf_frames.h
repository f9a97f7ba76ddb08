// A robot brought as a URDF, in tf as ROS 2's robot_state_publisher would put it: each link a
// frame R/urdf/<link> (a robot-model panel takes "R/urdf" as its TF prefix), the root link's
// frame fixed to R/base_link where the URDF places it above the ground, each joint the child
// link's frame in the parent's. The "urdf" part keeps the URDF's names apart from sanet's own
// frames (R/base_link, R/laser) even where the URDF uses the same words.
#pragma once

#include <array>
#include <vector>

#include "robots/node_model.h"
#include "ros2_presentation/robot_messages.h"

namespace sanet::ros2_presentation {

// R/urdf/<link>.
std::string UrdfLinkFrame(const RobotFrames& frames, const std::string& link);

// What does not move, stamped `t`: R/base_link -> the root, and every joint but the wheels' (other
// moving joints held at zero), appended to `out`.
void UrdfStaticTransforms(const robots::UrdfSource& urdf, const RobotFrames& frames, double t,
                          std::vector<msg::geometry_msgs::TransformStamped>& out);

// The wheel joints turned by the wheels' angles (rad, as the physics counts them: growing as the
// wheel drives its robot forward), stamped `t`, for /tf.
msg::tf2_msgs::TFMessage UrdfWheelTransforms(const robots::UrdfSource& urdf, const RobotFrames& frames, double t,
                                             const std::array<double, 3>& angles);

}  // namespace sanet::ros2_presentation
