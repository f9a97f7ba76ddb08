// What the IR ring's and the laser's scenario keys (sensors/ir, sensors/laser) share: a list of
// beam directions, read and printed.
#pragma once

#include <vector>

#include "scenario/fields.h"

namespace sanet::sensors {

YAML::Node AngleList(const std::vector<double>& angles);
std::vector<double> ReadAngles(const scenario::Field& field);

}  // namespace sanet::sensors
