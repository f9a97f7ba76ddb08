// An example controller library: `drive_to` turns towards a goal and drives straight to it,
// using nothing but the portable controller interface. It reports its steps (turning, driving,
// arrived) as transitions, its travel time as a metric, and its arrival by broadcast.
#include <sanet/plugin.h>

#include <cmath>
#include <memory>
#include <string>

namespace {

class DriveTo : public sanet::Controller {
 public:
  // Parameters come from the scenario's `params:`; every getter checks its value, and a key that
  // no getter reads is reported to the user as unknown.
  explicit DriveTo(const sanet::Params& p)
      : speed_(p.Number("speed", 0.4, 0.01, 5)), tolerance_(p.Number("tolerance", 0.2, 0.01, 10)) {
    const std::vector<double> goal = p.Numbers("goal", {});
    if (goal.size() != 2) throw sanet::ParamError("goal", p.Line("goal"), "parameter 'goal' must be [x, y]");
    goal_ = {goal[0], goal[1]};
  }

  void ControlStep(sanet::Node& node) override {
    if (arrived_) return;
    const std::optional<sanet::Pose2D> pose = node.GroundTruth();
    if (!pose) return;
    const sanet::Vec2 to_goal = goal_ - pose->position();
    if (sanet::Norm(to_goal) < tolerance_) {
      node.Drive({});
      Enter(node, "arrived", "within tolerance of the goal");
      node.Metric("travel_time", node.Now());
      node.Log("arrived");
      node.Broadcast({1});
      arrived_ = true;
      return;
    }
    const double error = sanet::WrapAngle(std::atan2(to_goal.y, to_goal.x) - pose->theta);
    // Turn first, then drive; slow down near the goal.
    const bool facing = std::abs(error) < 0.3;
    Enter(node, facing ? "driving" : "turning", facing ? "facing the goal" : "goal off the bow");
    const double v = facing ? std::min(speed_, sanet::Norm(to_goal)) : 0.0;
    node.Drive({v, 0, 1.5 * error});
  }

 private:
  void Enter(sanet::Node& node, const std::string& state, const std::string& why) {
    if (state == state_) return;
    node.Transition(state_, state, why);
    state_ = state;
  }

  std::string state_ = "start";
  double speed_, tolerance_;
  sanet::Vec2 goal_;
  bool arrived_ = false;
};

}  // namespace

// The library's entry point: register every controller it offers, by name.
SANET_CONTROLLER_PLUGIN(registry) {
  registry.Add({"drive_to", "turns towards `goal` [x, y] and drives there at `speed`, stopping within `tolerance`",
                [](const sanet::Params& p) { return std::make_unique<DriveTo>(p); }});
}
