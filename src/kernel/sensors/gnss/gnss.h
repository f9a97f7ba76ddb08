// A satellite receiver's position fix: the antenna's place (`mount_x`, `mount_y` from the
// reference point in the robot's frame, `height` above the ground) as latitude, longitude and
// altitude through the world's datum (GeographicLib's LocalCartesian: the world's x east, y north,
// z up, its origin at the datum), sampled at `rate` on the simulated clock. Each sample's error
// is Gaussian per axis (east and north of `horizontal_noise`, up of `vertical_noise`, standard
// deviations in m); with a `correlation_time` it is a first-order Gauss-Markov process of those
// deviations (the slow wander of a real receiver's error), else white. Inside a region without
// satellites (sensors/surroundings.h) the status is STATUS_NO_FIX and the position NaN. The error
// moves at every sample, from the seed, whether or not anyone reads.
#pragma once

namespace sanet::sensors {

struct GnssSettings {
  double rate = 5;                  // Hz
  double mount_x = 0, mount_y = 0;  // m, from the reference point, robot frame
  double height = 0;                // m, the antenna above the ground
  double horizontal_noise = 0;      // m, standard deviation east and north
  double vertical_noise = 0;        // m, standard deviation up
  double correlation_time = 0;      // s: 0 for white noise
};

}  // namespace sanet::sensors
