// formation_follower: keeps its place in the formation from the leader's last pose received
// (goal = leader pose composed with `offset`), with the behaviours of case study 2:
//   obstacle within `sensing_range` (180-degree laser): turn towards F_oa = F_o + F_g, where F_o
//     points away from the nearest obstacle with magnitude `k_o` / distance and F_g is the unit
//     vector to the goal; once oriented, drive straight for `commit_time` if the way is clear
//   heading off the goal by `t_o` or more: turn in place, omega = -`turn_gain` (theta - theta_g)
//   otherwise: drive straight, speed = `speed_gain` x the goal's distance ahead (capped)
// Leader poses are relayed to `forward_to`. Each reception logs the message's delay and how many
// poses were missed before it (metrics pose_delay and pose_missed).
#include <algorithm>
#include <cmath>
#include <memory>

#include "controllers.h"
#include "formation/pose_message.h"

namespace sanet::controllers {
namespace {

using formation::PoseMessage;

class FormationFollower : public Controller {
 public:
  explicit FormationFollower(const Params& p)
      : sensing_range_(p.Number("sensing_range", 1.0, 0.05, 100)),
        t_o_(p.Number("t_o", 0.2, 0.001, kPi)),
        turn_gain_(p.Number("turn_gain", 1.5, 0.01, 20)),
        speed_gain_(p.Number("speed_gain", 0.6, 0.01, 20)),
        max_speed_(p.Number("max_speed", 0.6, 0.01, 5)),
        k_o_(p.Number("k_o", 0.5, 0, 100)),
        commit_time_(p.Number("commit_time", 1.0, 0, 60)),
        goal_tolerance_(p.Number("goal_tolerance", 0.1, 0.01, 10)),
        forward_names_(p.Words("forward_to", {})) {
    const auto offset = p.Numbers("offset", {});
    if (offset.size() != 2)
      throw ParamError("offset", p.Line("offset"), "parameter 'offset' must be [dx, dy] (m, leader frame)");
    offset_ = {offset[0], offset[1]};
  }

  void Start(Node& node) override { forward_to_ = formation::Resolve(node, forward_names_, "formation_follower"); }

  void OnMessage(Node& node, const Message& message) override {
    const auto m = PoseMessage::Decode(message.payload);
    if (!m || (leader_ && m->sequence <= last_sequence_)) return;  // old or duplicate
    node.Metric("pose_delay", node.Now() - m->time);
    node.Metric("pose_missed", leader_ ? m->sequence - last_sequence_ - 1.0 : 0.0);
    last_sequence_ = m->sequence;
    leader_ = m->pose;
    for (NodeId to : forward_to_) node.Send(to, message.payload);
  }

  void ControlStep(Node& node) override {
    const auto pose = node.GroundTruth();
    if (!pose || !leader_) {
      node.Drive({});
      return;
    }
    const Vec2 goal = ToWorld(*leader_, offset_);
    const std::optional<RangeScan> scan = node.Laser();
    // Nearest obstacle within the sensing range, and how clear the way straight ahead is.
    double nearest = HUGE_VAL, nearest_angle = 0, ahead = HUGE_VAL;
    if (scan)
      for (std::size_t i = 0; i < scan->ranges.size(); ++i) {
        const double r = scan->ranges[i], a = scan->angles[i];
        if (r < nearest) nearest = r, nearest_angle = a;
        if (std::fabs(a) < 0.35) ahead = std::min(ahead, r);
      }
    const bool clear_ahead = ahead > 0.5;
    if (node.Now() < commit_until_ && clear_ahead) {
      node.Drive({0.5 * max_speed_, 0, 0});
      return;
    }
    const Vec2 to_goal = goal - pose->position();
    const double distance = Norm(to_goal);

    if (nearest < sensing_range_) {
      const Vec2 away = Rotate({-1, 0}, pose->theta + nearest_angle) * (k_o_ / std::max(nearest, 0.05));
      const Vec2 towards = distance > 1e-6 ? to_goal * (1 / distance) : Vec2{0, 0};
      const Vec2 f = away + towards;
      avoid_heading_ = std::atan2(f.y, f.x);
      if (!avoiding_) node.Log("obstacle at " + std::to_string(nearest) + " m: avoiding");
      avoiding_ = true;
    }
    // Turning away can take the obstacle out of the laser's half circle before the robot faces
    // theta_oa; the turn is finished all the same, or the goal would turn it back towards the
    // obstacle, and back again, for ever.
    if (avoiding_) {
      const double error = WrapAngle(pose->theta - avoid_heading_);
      if (std::fabs(error) >= t_o_) return void(node.Drive({0, 0, -turn_gain_ * error}));
      avoiding_ = nearest < sensing_range_;
      if (clear_ahead) {
        commit_until_ = node.Now() + commit_time_;  // a short move out of the way
        node.Drive({0.5 * max_speed_, 0, 0});
      } else {
        node.Drive({});
      }
      return;
    }
    if (distance < goal_tolerance_) {  // in place: face the way the leader faces
      node.Drive({0, 0, -turn_gain_ * WrapAngle(pose->theta - leader_->theta)});
      return;
    }
    const double error = WrapAngle(pose->theta - std::atan2(to_goal.y, to_goal.x));
    if (std::fabs(error) >= t_o_) {
      node.Drive({0, 0, -turn_gain_ * error});
    } else {
      const double ahead_of_us = ToLocal(*pose, goal).x;
      node.Drive({std::clamp(speed_gain_ * ahead_of_us, 0.0, max_speed_), 0, 0});
    }
  }

 private:
  double sensing_range_, t_o_, turn_gain_, speed_gain_, max_speed_, k_o_, commit_time_, goal_tolerance_;
  std::vector<std::string> forward_names_;
  Vec2 offset_;
  std::vector<NodeId> forward_to_;
  std::optional<Pose2D> leader_;
  std::uint32_t last_sequence_ = 0;
  double commit_until_ = 0;
  bool avoiding_ = false;  // turning towards theta_oa
  double avoid_heading_ = 0;
};

}  // namespace

ControllerInfo FormationFollowerInfo() {
  return {"formation_follower",
          "case study 2, follower: keeps `offset` [dx, dy] from the leader's last pose received, turning, "
          "driving straight or avoiding obstacles seen by its laser; relays poses to `forward_to`",
          [](const Params& p) { return std::make_unique<FormationFollower>(p); }};
}

}  // namespace sanet::controllers
