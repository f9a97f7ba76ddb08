// `sanet merge`: a team's agents' results folders (sanet agent --ros2) on one time line
// (docs/ros2-robots.md#a-teams-results-on-one-time-line).
#pragma once

#include "options.h"

namespace sanet::cli {

Command AddMerge(CLI::App& app);

}  // namespace sanet::cli
