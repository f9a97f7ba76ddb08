// Wheel odometry: the pose integrated from the wheels' rotation, from the robot's start pose.
#pragma once

namespace sanet::sensors {

struct OdometrySettings {
  double noise = 0;  // relative standard deviation of every increment of travel and turn
};

}  // namespace sanet::sensors
