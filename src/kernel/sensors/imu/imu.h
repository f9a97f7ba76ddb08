// An inertial measurement unit: the body's angular velocity and specific force (acceleration
// less gravity: at rest on flat ground, +g upwards) in the IMU's frame, the robot's axes at a
// mount `mount_x`, `mount_y` from its reference point, sampled at `rate` on the simulated clock.
// sanet's bodies move in the plane: the angular velocity is about z, the acceleration's z is
// gravity's. Noise as Kalibr, RotorS and PX4 give it, per axis: white noise of a density
// (units/sqrt(Hz), so a sample's standard deviation is density * sqrt(rate)) on a bias that
// walks as a Wiener process (its random walk in units/s/sqrt(Hz): each sample's bias moves by
// walk / sqrt(rate)), both drawn at every sample from the seed whether or not anyone reads.
#pragma once

namespace sanet::sensors {

struct ImuSettings {
  double rate = 100;                       // Hz
  double mount_x = 0, mount_y = 0;         // m, from the reference point, robot frame
  bool orientation = false;                // give the orientation (the body's yaw, exact); else covariance[0] = -1
  double gyroscope_noise_density = 0;      // rad/s/sqrt(Hz)
  double gyroscope_random_walk = 0;        // rad/s^2/sqrt(Hz)
  double accelerometer_noise_density = 0;  // m/s^2/sqrt(Hz)
  double accelerometer_random_walk = 0;    // m/s^3/sqrt(Hz)
};

}  // namespace sanet::sensors
