// Visits a list of way points in order, going round obstacles it meets, and stops at the last.
#include <memory>

#include "controllers.h"
#include "navigation.h"

namespace sanet::controllers {
namespace {

class Waypoint : public Controller {
 public:
  explicit Waypoint(const Params& p)
      : pilot_(PilotSettings::FromParams(p)),
        tolerance_(p.Number("tolerance", 0.3, 0.01)),
        use_odometry_(p.Text("localization", "ground_truth") == "odometry"),
        loop_(p.Flag("loop", false)) {
    const std::string localization = p.Text("localization", "ground_truth");
    if (localization != "ground_truth" && localization != "odometry")
      throw ParamError("localization", 0, "parameter 'localization' must be ground_truth or odometry");
    for (const auto& row : p.Table("waypoints", 2, {})) points_.push_back({row[0], row[1]});
    if (points_.empty()) throw ParamError("waypoints", 0, "parameter 'waypoints' is required: [[x, y], ...]");
  }

  void ControlStep(Node& node) override {
    if (next_ >= points_.size()) return;
    const std::optional<Pose2D> pose = use_odometry_ ? node.Odometry() : node.GroundTruth();
    if (!pose) return;
    if (Norm(points_[next_] - pose->position()) < tolerance_) {
      node.Log("reached waypoint " + std::to_string(next_));
      pilot_.Reset();
      if (++next_ == points_.size()) {
        if (!loop_) {
          node.Drive({});
          node.Log("arrived");
          return;
        }
        next_ = 0;
      }
    }
    std::optional<RangeScan> scan = node.Laser();
    if (!scan) scan = node.Ir();
    const bool was_following = pilot_.following();
    node.Drive(pilot_.Steer(node.Now(), *pose, points_[next_], scan ? &*scan : nullptr, node.Holonomic()));
    if (pilot_.following() != was_following)
      node.Log(pilot_.following() ? "obstacle: following its boundary" : "way clear: heading for the goal");
  }

 private:
  Pilot pilot_;
  double tolerance_;
  bool use_odometry_;
  bool loop_;
  std::vector<Vec2> points_;
  std::size_t next_ = 0;
};

}  // namespace

ControllerInfo WaypointInfo() {
  return {"waypoint",
          "visits `waypoints` ([[x, y], ...] m) in order at `speed`, going round obstacles seen by "
          "its laser or IR ring; stops within `tolerance` of the last (or starts over with `loop`)",
          [](const Params& p) { return std::make_unique<Waypoint>(p); }};
}

}  // namespace sanet::controllers
