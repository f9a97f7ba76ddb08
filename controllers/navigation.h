// A local planner for going to a point among obstacles seen only by range sensors: head for the
// goal; when something blocks the way, follow its boundary (keeping it on one side) until the
// goal is nearer than where the obstacle was met and the way towards it is clear (the idea of
// the Bug2 family). Written against the controller interface only.
#pragma once

#include <optional>

#include "sanet/node.h"
#include "sanet/params.h"

namespace sanet::controllers {

struct PilotSettings {
  double speed = 0.5;             // m/s, cruise speed
  double safe_distance = 0.5;     // m: an obstacle nearer than this ahead starts boundary following
  double follow_distance = 0.35;  // m kept from the obstacle while following it
  double turn_gain = 2.0;         // rad/s per rad of heading error

  static PilotSettings FromParams(const Params& p);
};

class Pilot {
 public:
  explicit Pilot(PilotSettings settings) : s_(settings) {}

  // Velocity (robot frame) that moves `pose` towards `goal`, given the latest ranges (robot frame)
  // at time `now` (s).
  Twist2D Steer(double now, const Pose2D& pose, Vec2 goal, const RangeScan* scan, bool holonomic);
  bool following() const { return mode_ == Mode::kFollow; }
  void SetSpeed(double speed) { s_.speed = speed; }
  void Reset() { mode_ = Mode::kGoal; }

 private:
  enum class Mode { kGoal, kFollow };
  // World heading to move along.
  double ChooseHeading(const Pose2D& pose, Vec2 goal, const RangeScan* scan, double dt);

  PilotSettings s_;
  Mode mode_ = Mode::kGoal;
  double side_ = 1;                     // +1: obstacle kept on the right (we go round it anticlockwise)
  double hit_distance_ = 0;             // distance to the goal where the obstacle was met
  double last_heading_ = 0;             // world heading while following
  std::optional<double> hold_heading_;  // holonomic robots keep their initial heading
  std::optional<double> last_time_;
};

}  // namespace sanet::controllers
