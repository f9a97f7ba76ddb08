#include "robots/kinematics.h"

#include <cmath>
#include <stdexcept>

namespace sanet::robots {

Omni3Kinematics::Omni3Kinematics(std::array<double, 3> angles, double distance, double wheel_radius)
    : wheel_radius_(wheel_radius) {
  for (int i = 0; i < 3; ++i) {
    m_[i][0] = -std::sin(angles[i]);
    m_[i][1] = std::cos(angles[i]);
    m_[i][2] = distance;
  }
  // 3x3 inverse by cofactors.
  const double det = m_[0][0] * (m_[1][1] * m_[2][2] - m_[1][2] * m_[2][1]) -
                     m_[0][1] * (m_[1][0] * m_[2][2] - m_[1][2] * m_[2][0]) +
                     m_[0][2] * (m_[1][0] * m_[2][1] - m_[1][1] * m_[2][0]);
  if (std::fabs(det) < 1e-9) throw std::invalid_argument("omni3 wheel angles give no inverse");
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      m_inv_[r][c] = (m_[r1][c1] * m_[r2][c2] - m_[r1][c2] * m_[r2][c1]) / det;
    }
}

// The hinge axis points outwards, so a positive spin moves the rim against the tangent.
std::vector<double> Omni3Kinematics::WheelSpeeds(const Twist2D& b) const {
  std::vector<double> w(3);
  for (int i = 0; i < 3; ++i) w[i] = -(m_[i][0] * b.vx + m_[i][1] * b.vy + m_[i][2] * b.omega) / wheel_radius_;
  return w;
}

Twist2D Omni3Kinematics::BodyTwist(const std::vector<double>& w) const {
  double rim[3];
  for (int i = 0; i < 3; ++i) rim[i] = -w.at(i) * wheel_radius_;
  double out[3];
  for (int r = 0; r < 3; ++r) out[r] = m_inv_[r][0] * rim[0] + m_inv_[r][1] * rim[1] + m_inv_[r][2] * rim[2];
  return {out[0], out[1], out[2]};
}

std::vector<double> DiffDriveKinematics::WheelSpeeds(const Twist2D& b) const {
  return {(b.vx - b.omega * axle_ / 2) / radius_, (b.vx + b.omega * axle_ / 2) / radius_};
}

Twist2D DiffDriveKinematics::BodyTwist(const std::vector<double>& w) const {
  return {radius_ * (w.at(0) + w.at(1)) / 2, 0, radius_ * (w.at(1) - w.at(0)) / axle_};
}

}  // namespace sanet::robots
