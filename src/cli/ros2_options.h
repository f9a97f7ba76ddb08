// `sanet serve --ros2`: the options of the ROS 2 face and its start.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>

#include "ros2_face/ros2_face.h"
#include "sim/world.h"

namespace sanet::cli {

struct Ros2Args {
  bool on = false;
  std::optional<int> domain;  // default: ROS_DOMAIN_ID, else 0
  double rate = 10;           // Hz of each robot's sensor messages
  bool stamped = false;       // cmd_vel as TwistStamped
};

void AddRos2Options(CLI::App* cmd, Ros2Args& args);
// Joins the DDS domain and starts the face (nothing without --ros2); a domain that cannot be
// joined is an error naming the option.
std::unique_ptr<ros2face::Ros2Face> StartRos2Face(sim::World& world, const Ros2Args& args);

}  // namespace sanet::cli
