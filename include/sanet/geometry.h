// Plane geometry shared by the whole project and by controllers: SI units, z-up,
// angles in radians counter-clockwise from the x axis.
#pragma once

#include <cmath>

namespace sanet {

constexpr double kPi = 3.14159265358979323846;

struct Vec2 {
  double x = 0;
  double y = 0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(Vec2 a, double k) { return {a.x * k, a.y * k}; }
inline double Dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double Norm(Vec2 a) { return std::hypot(a.x, a.y); }
inline Vec2 Rotate(Vec2 a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * a.x - s * a.y, s * a.x + c * a.y};
}

// Wraps an angle into (-pi, pi].
inline double WrapAngle(double a) {
  a = std::fmod(a + kPi, 2 * kPi);
  if (a <= 0) a += 2 * kPi;
  return a - kPi;
}

// Position and heading on the ground plane.
struct Pose2D {
  double x = 0;
  double y = 0;
  double theta = 0;  // rad, counter-clockwise from +x
  Vec2 position() const { return {x, y}; }
};

// A point expressed in the frame of `pose`, seen in the world frame.
inline Vec2 ToWorld(const Pose2D& pose, Vec2 local) { return pose.position() + Rotate(local, pose.theta); }
// A world point seen in the frame of `pose`.
inline Vec2 ToLocal(const Pose2D& pose, Vec2 world) { return Rotate(world - pose.position(), -pose.theta); }

// A planar velocity: linear part (m/s) and yaw rate (rad/s). Its frame is said where used.
struct Twist2D {
  double vx = 0;
  double vy = 0;
  double omega = 0;
};

}  // namespace sanet
