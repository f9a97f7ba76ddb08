// formation_leader: drives a polygon (the rhombus of case study 2) corner to corner, turning in
// place at each corner, and sends its pose at `rate` Hz to the robots named in `send_to`.
#include <cmath>
#include <memory>

#include "controllers.h"
#include "formation/pose_message.h"

namespace sanet::controllers {
namespace {

class FormationLeader : public Controller {
 public:
  explicit FormationLeader(const Params& p)
      : speed_(p.Number("speed", 0.3, 0.01, 5)),
        turn_gain_(p.Number("turn_gain", 1.0, 0.01, 20)),
        tolerance_(p.Number("tolerance", 0.2, 0.01, 10)),
        heading_tolerance_(p.Number("heading_tolerance", 0.05, 0.001, kPi)),
        period_(1.0 / p.Number("rate", 10, 0.1, 1000)),
        laps_(p.Integer("laps", 1, 1, 1000)),
        silent_after_(p.Number("silent_after", HUGE_VAL, 0)),
        send_to_names_(p.Words("send_to", {})) {
    for (const auto& c : p.Table("corners", 2, {})) corners_.push_back({c[0], c[1]});
    if (corners_.size() < 2)
      throw ParamError("corners", p.Line("corners"), "parameter 'corners' needs at least 2 points");
  }

  void Start(Node& node) override { send_to_ = formation::Resolve(node, send_to_names_, "formation_leader"); }

  void ControlStep(Node& node) override {
    const auto pose = node.GroundTruth();
    if (!pose) return;
    if (node.Now() + 1e-9 >= next_send_ && node.Now() < silent_after_) {
      next_send_ = node.Now() + period_;
      // Numbered by its slot on the send grid, so a pose that was due but never sent (a late
      // step in the loop) shows as a gap to the followers, like one lost on the way.
      const auto slot = static_cast<std::uint32_t>(std::llround(node.Now() / period_));
      const Bytes message = formation::PoseMessage{slot, node.Now(), *pose}.Encode();
      for (NodeId to : send_to_) node.Send(to, message);
    }
    if (done_) {
      node.Drive({});
      return;
    }
    const Vec2 goal = corners_[next_];
    const Vec2 to_goal = goal - pose->position();
    if (Norm(to_goal) < tolerance_) {
      node.Log("corner " + std::to_string(next_) + " at " + std::to_string(node.Now()) + " s");
      next_ = (next_ + 1) % corners_.size();
      if (next_ == 1 && ++lap_ >= laps_) {
        done_ = true;
        node.Log("laps done");
      }
      return;
    }
    const double error = WrapAngle(std::atan2(to_goal.y, to_goal.x) - pose->theta);
    // Turn in place until facing the corner, then drive straight with small corrections.
    if (std::fabs(error) > heading_tolerance_ && std::fabs(error) > 0.3)
      node.Drive({0, 0, turn_gain_ * error});
    else
      node.Drive({std::min(speed_, Norm(to_goal)), 0, turn_gain_ * error});
  }

 private:
  double speed_, turn_gain_, tolerance_, heading_tolerance_, period_;
  int laps_;
  double silent_after_;
  std::vector<std::string> send_to_names_;
  std::vector<Vec2> corners_;
  std::vector<NodeId> send_to_;
  std::size_t next_ = 1;
  int lap_ = 0;
  bool done_ = false;
  double next_send_ = 0;
};

}  // namespace

ControllerInfo FormationLeaderInfo() {
  return {"formation_leader",
          "case study 2, leader: drives `corners` ([[x, y], ...], starting at the first) for `laps` at "
          "`speed`, sending its pose at `rate` Hz to the robots in `send_to` (names) until `silent_after` s",
          [](const Params& p) { return std::make_unique<FormationLeader>(p); }};
}

}  // namespace sanet::controllers
