// The node's true pose, with optional Gaussian noise (a tracking system's error).
#pragma once

namespace sanet::sensors {

struct GroundTruthSettings {
  double noise_position = 0;  // m, standard deviation added to x and y
  double noise_angle = 0;     // rad, standard deviation added to theta
};

}  // namespace sanet::sensors
