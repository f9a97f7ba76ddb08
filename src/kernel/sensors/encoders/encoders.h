// Wheel encoders: each wheel's angle and speed, as the physics turns it. Angles count from the
// start of the run, unwrapped, in whole ticks of `resolution` when one is given (an incremental
// encoder's count); speeds are the mean over the time since the previous reading, with Gaussian
// noise. The joints are named as the robot's URDF names its wheel joints, else by the model
// (a diffdrive's left_wheel_joint and right_wheel_joint, an omni3's wheel_0_joint to
// wheel_2_joint).
#pragma once

#include <string>
#include <vector>

namespace sanet::sensors {

struct EncodersSettings {
  double rate = 50;                // Hz: samples a second, on the simulated clock
  double resolution = 0;           // rad per tick; 0: the exact angle
  double noise = 0;                // rad/s, standard deviation of each speed
  std::vector<std::string> names;  // per wheel (not a scenario key: from the model)
};

}  // namespace sanet::sensors
