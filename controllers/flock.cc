// Flocking over one-hop radio beacons (after Reynolds' boids), for swarms. Every `beacon` s,
// from a random phase so that neighbours do not all send at once, a robot broadcasts its
// position and heading to whoever hears it. At every step it steers by four urges: away from
// neighbours nearer than `separation`, along the neighbours' mean heading (alignment), towards
// their mean position (cohesion), and away from whatever its range sensors (IR ring or laser)
// see nearer than `avoid`, plus a small random wander; it drives at `speed`, slower while it
// turns hard. Neighbours are those heard within the last `forget` s. Every beacon it also
// reports how many neighbours it has (metric `neighbours`).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include "controllers.h"
#include "sanet/codec.h"

namespace sanet::controllers {
namespace {

struct Heard {
  Vec2 position;
  double heading = 0;
  double time = 0;
};

class Flock : public Controller {
 public:
  explicit Flock(const Params& p)
      : speed_(p.Number("speed", 0.3, 0.01, 10)),
        separation_(p.Number("separation", 5, 0)),
        avoid_(p.Number("avoid", 0.8, 0)),
        beacon_(p.Number("beacon", 1, 0.01)),
        forget_(p.Number("forget", 3, 0)),
        cohesion_weight_(p.Number("cohesion", 0.2, 0)),
        alignment_weight_(p.Number("alignment", 0.5, 0)),
        separation_weight_(p.Number("separation_weight", 1.5, 0)),
        avoid_weight_(p.Number("avoid_weight", 4, 0)),
        wander_(p.Number("wander", 0.3, 0)),
        max_turn_(p.Number("max_turn", 1.5, 0.01)) {}

  void Start(Node& node) override {
    if (!node.Drive({}))
      throw std::runtime_error("flock: needs a robot that can drive, and " + node.Name() + " cannot");
    if (!node.GroundTruth() && !node.Odometry())
      throw std::runtime_error("flock: needs ground truth or odometry to know where it is");
    next_beacon_ = node.Now() + beacon_ * node.Random();
  }

  void OnMessage(Node& node, const Message& m) override {
    Reader r(m.payload);
    const Vec2 position{r.F64(), r.F64()};
    const double heading = r.F64();
    if (r.ok()) heard_[m.from] = {position, heading, node.Now()};
  }

  void ControlStep(Node& node) override {
    std::optional<Pose2D> pose = node.GroundTruth();
    if (!pose) pose = node.Odometry();
    const double now = node.Now();
    Forget(now);
    if (now >= next_beacon_) {
      next_beacon_ += beacon_;
      node.Broadcast(Writer().F64(pose->x).F64(pose->y).F64(pose->theta).bytes());
      node.Metric("neighbours", static_cast<double>(heard_.size()));
    }
    const Vec2 forward{std::cos(pose->theta), std::sin(pose->theta)};
    const Vec2 urge = forward + Neighbours(*pose) + Obstacles(node, *pose);
    const double error = WrapAngle(std::atan2(urge.y, urge.x) - pose->theta);
    const double turn = std::clamp(2 * error + wander_ * (2 * node.Random() - 1), -max_turn_, max_turn_);
    node.Drive({speed_ * std::max(0.0, std::cos(error)), 0, turn});
  }

 private:
  void Forget(double now) {
    for (auto it = heard_.begin(); it != heard_.end();) it = now - it->second.time > forget_ ? heard_.erase(it) : ++it;
  }

  Vec2 Neighbours(const Pose2D& pose) const {
    if (heard_.empty()) return {};
    Vec2 away{}, centre{}, heading{};
    for (const auto& [id, n] : heard_) {
      const Vec2 offset = pose.position() - n.position;
      const double d = Norm(offset);
      if (d > 1e-6 && d < separation_) away = away + offset * ((separation_ - d) / (separation_ * d));
      centre = centre + n.position;
      heading = heading + Vec2{std::cos(n.heading), std::sin(n.heading)};
    }
    const double count = static_cast<double>(heard_.size());
    const Vec2 to_centre = centre * (1 / count) - pose.position();
    const double spread = std::max(Norm(to_centre), 1.0);
    return away * separation_weight_ + heading * (alignment_weight_ / count) + to_centre * (cohesion_weight_ / spread);
  }

  // Each beam that sees something nearer than `avoid` pushes the robot away from it, the harder
  // the nearer.
  Vec2 Obstacles(Node& node, const Pose2D& pose) const {
    std::optional<RangeScan> scan = node.Ir();
    if (!scan) scan = node.Laser();
    if (!scan || avoid_ <= 0) return {};
    Vec2 push{};
    for (std::size_t i = 0; i < scan->ranges.size(); ++i) {
      if (scan->ranges[i] >= avoid_) continue;
      const double a = pose.theta + scan->angles[i];
      push = push - Vec2{std::cos(a), std::sin(a)} * ((avoid_ - scan->ranges[i]) / avoid_);
    }
    return push * avoid_weight_;
  }

  double speed_, separation_, avoid_, beacon_, forget_;
  double cohesion_weight_, alignment_weight_, separation_weight_, avoid_weight_, wander_, max_turn_;
  double next_beacon_ = 0;
  std::map<NodeId, Heard> heard_;
};

}  // namespace

ControllerInfo FlockInfo() {
  return {"flock",
          "flocks by one-hop beacons (position, heading) every `beacon` s: keeps `separation` from "
          "neighbours, aligns with them, drifts to their centre, avoids what its IR or laser sees "
          "nearer than `avoid`; drives at `speed`",
          [](const Params& p) { return std::make_unique<Flock>(p); }};
}

}  // namespace sanet::controllers
