// The laser as ROS 2 sees it: sensor_msgs/LaserScan (REP 117: a beam that saw nothing reads +Inf).
#pragma once

#include <string>

#include "ros2msg/messages.h"
#include "sanet/readings.h"

namespace sanet::ros2_presentation {

ros2msg::sensor_msgs::LaserScan ScanOf(const RangeScan& scan, double t, const std::string& frame);

}  // namespace sanet::ros2_presentation
