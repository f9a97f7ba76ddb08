// Wheel kinematics of the robot models: body velocity (robot frame) to wheel speeds and back.
// The same formulas drive the motors and integrate odometry.
#pragma once

#include <array>
#include <vector>

#include "sanet/geometry.h"

namespace sanet::robots {

class Kinematics {
 public:
  virtual ~Kinematics() = default;
  virtual bool holonomic() const = 0;
  virtual std::vector<double> WheelSpeeds(const Twist2D& body) const = 0;  // rad/s per wheel
  // Inverse of WheelSpeeds: also turns wheel rotation increments into a body displacement.
  virtual Twist2D BodyTwist(const std::vector<double>& wheel_rates) const = 0;
};

// Three omni wheels at `angles` (rad from forward), `distance` from the centre, spinning about
// radial axes: a wheel's rim moves along the tangent (-sin a, cos a).
class Omni3Kinematics : public Kinematics {
 public:
  Omni3Kinematics(std::array<double, 3> angles, double distance, double wheel_radius);
  bool holonomic() const override { return true; }
  std::vector<double> WheelSpeeds(const Twist2D& body) const override;
  Twist2D BodyTwist(const std::vector<double>& wheel_rates) const override;

 private:
  double m_[3][3];  // rim speeds = m * (vx, vy, omega)
  double m_inv_[3][3];
  double wheel_radius_;
};

// Two wheels on one axle; wheel 0 left, wheel 1 right.
class DiffDriveKinematics : public Kinematics {
 public:
  DiffDriveKinematics(double axle_length, double wheel_radius) : axle_(axle_length), radius_(wheel_radius) {}
  bool holonomic() const override { return false; }
  std::vector<double> WheelSpeeds(const Twist2D& body) const override;
  Twist2D BodyTwist(const std::vector<double>& wheel_rates) const override;

 private:
  double axle_, radius_;
};

}  // namespace sanet::robots
