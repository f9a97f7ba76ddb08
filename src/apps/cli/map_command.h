// `sanet map`: the scenario's world as a ROS map (map_server's YAML and PGM), for Nav2's map
// server and AMCL (docs/ros2.md#nav2-on-a-sanet-world).
#pragma once

#include "options.h"

namespace sanet::cli {

Command AddMap(CLI::App& app);

}  // namespace sanet::cli
