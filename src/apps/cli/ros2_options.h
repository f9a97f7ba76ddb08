// `sanet serve --ros2`: the options of the ROS 2 face and its start.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>

#include "ros2_face/ros2_face.h"
#include "sim/world.h"

namespace sanet::cli {

// Given on the command line; each overrides the scenario's ros2 section.
struct Ros2Args {
  bool on = false, off = false;          // --ros2, --no-ros2
  std::optional<int> domain;             // default: the section's, else ROS_DOMAIN_ID, else 0
  std::optional<double> rate;            // Hz of each robot's sensor messages
  bool stamped = false;                  // cmd_vel as TwistStamped
  std::optional<std::string> interface;  // --ros2-interface: the face's network interface
  std::optional<std::string> distro;     // --ros2-distro: humble or jazzy
};

void AddRos2Options(CLI::App* cmd, Ros2Args& args);
// The DDS domain: the option's, else the scenario section's (>= 0), else ROS_DOMAIN_ID, else 0;
// an invalid ROS_DOMAIN_ID is an error naming it.
int Ros2Domain(std::optional<int> given, int section);
// Joins the DDS domain and starts the face, when the scenario has a ros2 section or --ros2 is
// given (and --no-ros2 is not); a domain that cannot be joined is an error naming the option.
// Adds the line that says where the face is to `notices`.
std::unique_ptr<ros2_face::Ros2Face> StartRos2Face(sim::World& world, const Ros2Args& args,
                                                   const std::optional<sections::Ros2Spec>& section,
                                                   std::vector<std::string>& notices);

}  // namespace sanet::cli
