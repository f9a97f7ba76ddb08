// An ultrasonic range finder: the nearest thing within a cone, one range per reading (as a
// sonar's echo gives it). The worked example of docs/architecture.md ("Adding a sensor").
#pragma once

namespace sanet::sensors {

struct SonarSettings {
  double direction = 0;     // rad, robot frame: where the cone points
  double fov = 0.5;         // rad, the cone's full width
  int rays = 9;             // rays sampling the cone, evenly spread over it
  double max_range = 4.0;   // m
  double height = 0.15;     // m above the ground
  double mount_radius = 0;  // m out from the reference point along `direction` (the body's edge by default)
  double noise = 0;         // m, standard deviation of the range
};

}  // namespace sanet::sensors
