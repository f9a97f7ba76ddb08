#include "navigation.h"

#include <algorithm>
#include <cmath>

namespace sanet::controllers {
namespace {

constexpr double kSector = kPi / 3;  // half-width of the "ahead" sector around the goal direction

}  // namespace

PilotSettings PilotSettings::FromParams(const Params& p) {
  PilotSettings s;
  s.speed = p.Number("speed", s.speed, 0.01, 10);
  s.safe_distance = p.Number("safe_distance", s.safe_distance, 0.05, 50);
  s.follow_distance = p.Number("follow_distance", s.follow_distance, 0.05, 50);
  s.turn_gain = p.Number("turn_gain", s.turn_gain, 0.01, 100);
  return s;
}

double Pilot::ChooseHeading(const Pose2D& pose, Vec2 goal, const RangeScan* scan, double dt) {
  const Vec2 to_goal = goal - pose.position();
  const double goal_heading = std::atan2(to_goal.y, to_goal.x);
  const double distance = Norm(to_goal);
  if (!scan || scan->ranges.empty()) return goal_heading;

  // Nearest reading overall and nearest in the sector towards the goal (robot frame angles).
  const double goal_local = WrapAngle(goal_heading - pose.theta);
  double nearest = scan->max_range, nearest_angle = 0, ahead = scan->max_range;
  double left_room = 0, right_room = 0;
  for (std::size_t i = 0; i < scan->ranges.size(); ++i) {
    const double r = scan->ranges[i], a = scan->angles[i];
    if (r < nearest) nearest = r, nearest_angle = a;
    const double off = WrapAngle(a - goal_local);
    if (std::fabs(off) < kSector) ahead = std::min(ahead, r);
    (off > 0 ? left_room : right_room) += r;
  }

  if (mode_ == Mode::kGoal) {
    if (ahead >= s_.safe_distance || distance < ahead) return goal_heading;
    mode_ = Mode::kFollow;
    hit_distance_ = distance;
    side_ = left_room >= right_room ? 1 : -1;  // pass on the side with more room
    last_heading_ = goal_heading;
  } else if (ahead >= s_.safe_distance && distance < hit_distance_ - 0.05) {
    mode_ = Mode::kGoal;
    return goal_heading;
  }

  if (nearest >= scan->max_range) {
    // Lost the boundary (past a corner): curve towards the side it was on, on a circle a little
    // wider than the distance kept, so as to come round the corner without hitting it.
    const double radius = s_.follow_distance + s_.safe_distance;
    last_heading_ = WrapAngle(last_heading_ - side_ * s_.speed * dt / radius);
    return last_heading_;
  }
  // Move along the boundary: perpendicular to the nearest reading, leaning in when too far and
  // out when too near.
  const double lean = std::clamp(2.0 * (nearest - s_.follow_distance), -kPi / 4, kPi / 4);
  last_heading_ = WrapAngle(pose.theta + nearest_angle + side_ * (kPi / 2 - lean));
  return last_heading_;
}

Twist2D Pilot::Steer(double now, const Pose2D& pose, Vec2 goal, const RangeScan* scan, bool holonomic) {
  const double dt = last_time_ ? std::clamp(now - *last_time_, 0.0, 1.0) : 0.1;
  last_time_ = now;
  const double heading = ChooseHeading(pose, goal, scan, dt);
  const double distance = Norm(goal - pose.position());
  const double speed = std::min(s_.speed, 0.8 * distance + 0.05);
  if (holonomic) {
    if (!hold_heading_) hold_heading_ = pose.theta;
    const Vec2 v = Rotate({speed, 0}, heading - pose.theta);
    return {v.x, v.y, s_.turn_gain * WrapAngle(*hold_heading_ - pose.theta)};
  }
  const double error = WrapAngle(heading - pose.theta);
  return {speed * std::max(0.0, std::cos(error)), 0, s_.turn_gain * error};
}

}  // namespace sanet::controllers
