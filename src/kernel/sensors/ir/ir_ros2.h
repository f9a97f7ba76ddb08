// The IR ring as ROS 2 sees it: one sensor_msgs/Range per sensor.
#pragma once

#include <cstddef>
#include <string>

#include "ros2msg/messages.h"
#include "sanet/readings.h"

namespace sanet::ros2_presentation {

// IR sensor `i`: one ray (field of view 0), its noise's variance.
ros2msg::sensor_msgs::Range RangeOf(const RangeScan& ir, std::size_t i, double t, const std::string& frame,
                                    double noise);

}  // namespace sanet::ros2_presentation
