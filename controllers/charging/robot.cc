// A robot that keeps a sensor network alive (case study 3, docs/case-study-charging.md): it
// listens to the motes' battery reports (charging/mote.cc), which reach it over the multi-hop
// network, and drives to the mote it expects to be lowest, as long as that one is expected below
// `threshold`: the charge last reported less what the mote has been seen to use since. There it
// parks at `park_offset` from the mote and its wireless charger (energy.wireless_charger) powers
// the mote until the mote reports `full`, or `max_charge_s` has passed. With nothing to do, or
// its own battery below `self_low`, it goes back to `dock` (a charger in the world) and stays
// until it is above `self_full`, or leaves earlier, once 5 % above `self_low`, for a mote expected
// below `urgent`. `visits: false` keeps it at the dock (the network without it).
// Metrics: visits (1 per visit begun), charge_s (each visit's length), reports (1 per report
// heard), docked (1 per return to the dock for its own battery).
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

#include "charging/messages.h"
#include "controllers.h"

namespace sanet::controllers {
namespace {

struct MoteState {
  charging::Report last;
  double use_per_s = 0;  // of the charge, seen between two reports while it was not charging
};

class ChargerRobot : public Controller {
 public:
  explicit ChargerRobot(const Params& p)
      : dock_(Point(p, "dock", {0, 0})),
        park_offset_(Point(p, "park_offset", {0, -0.45})),
        threshold_(p.Number("threshold", 0.5, 0, 1)),
        full_(p.Number("full", 0.95, 0, 1)),
        self_low_(p.Number("self_low", 0.3, 0, 1)),
        self_full_(p.Number("self_full", 0.9, 0, 1)),
        urgent_(p.Number("urgent", 0.15, 0, 1)),
        speed_(p.Number("speed", 0.8, 0.01)),
        max_charge_s_(p.Number("max_charge_s", 900, 1)),
        visits_(p.Flag("visits", true)) {}

  void OnMessage(Node& node, const Message& m) override {
    const std::optional<charging::Report> r = charging::ReadReport(m.payload);
    if (!r) return;
    node.Metric("reports", 1);
    MoteState& mote = motes_[m.from];
    const charging::Report& before = mote.last;
    if (before.time > 0 && r->time > before.time && !before.charging && !r->charging)
      mote.use_per_s = std::max(0.0, (before.fraction - r->fraction) / (r->time - before.time));
    if (r->time >= before.time) mote.last = *r;
  }

  void ControlStep(Node& node) override {
    const std::optional<Pose2D> pose = node.GroundTruth();
    const std::optional<BatteryReading> own = node.SensorAs<BatteryReading>("battery");
    if (!pose || !own)
      throw std::runtime_error("charger_robot: the robot needs `energy` and its battery sensor (not `battery: false`)");
    switch (state_) {
      case State::kDocked:
        return Docked(node, *own);
      case State::kToDock:
        return Drive(node, *pose, dock_) ? Enter(node, State::kDocked, "at the dock") : void();
      case State::kToMote:
        return Drive(node, *pose, Parking()) ? Arrive(node) : void();
      case State::kCharging:
        return Charging(node, *own);
    }
  }

 private:
  enum class State { kDocked, kToDock, kToMote, kCharging };

  static Vec2 Point(const Params& p, const std::string& key, std::vector<double> fallback) {
    const std::vector<double> v = p.Numbers(key, std::move(fallback));
    if (v.size() != 2) throw ParamError(key, p.Line(key), "parameter '" + key + "' must be [x, y]");
    return {v[0], v[1]};
  }

  static const char* Name(State s) {
    switch (s) {
      case State::kDocked:
        return "docked";
      case State::kToDock:
        return "to_dock";
      case State::kToMote:
        return "to_mote";
      case State::kCharging:
        return "charging";
    }
    return "";
  }

  void Enter(Node& node, State next, const std::string& why) {
    node.Transition(Name(state_), Name(next), why);
    state_ = next;
    since_ = node.Now();
  }

  // At the dock it charges itself first (unless a mote is about to die), then leaves for the
  // mote most in need.
  void Docked(Node& node, const BatteryReading& own) {
    node.Drive({0, 0, 0});
    if (own.fraction < self_full_ && (self_charging_ || own.fraction < self_low_)) {
      self_charging_ = true;
      if (own.fraction < self_low_ + 0.05 || !ChooseTarget(node, urgent_)) return;
    } else if (!ChooseTarget(node, threshold_)) {
      return;
    }
    self_charging_ = false;
    Enter(node, State::kToMote, "going to " + node.NameOf(*target_));
  }

  void Arrive(Node& node) {
    node.Metric("visits", 1);
    Enter(node, State::kCharging, "charging " + node.NameOf(*target_));
  }

  // Until the mote reports full (after the robot arrived) or the visit is too long; then the
  // next mote, or the dock.
  void Charging(Node& node, const BatteryReading& own) {
    node.Drive({0, 0, 0});
    const charging::Report& r = motes_.at(*target_).last;
    const bool done = (r.time >= since_ && r.fraction >= full_) || node.Now() - since_ >= max_charge_s_;
    if (!done) return;
    node.Metric("charge_s", node.Now() - since_);
    motes_.at(*target_).last.fraction = std::max(r.fraction, full_);  // until its next report
    if (own.fraction < self_low_) {
      node.Metric("docked", 1);
      return Enter(node, State::kToDock, "its own battery is low");
    }
    if (ChooseTarget(node, threshold_)) return Enter(node, State::kToMote, "going to " + node.NameOf(*target_));
    Enter(node, State::kToDock, "no mote needs charge");
  }

  // The mote expected lowest now, if below `below`.
  bool ChooseTarget(Node& node, double below) {
    target_.reset();
    if (!visits_) return false;
    double lowest = below;
    for (const auto& [id, mote] : motes_) {
      const double expected = mote.last.fraction - mote.use_per_s * (node.Now() - mote.last.time);
      if (expected < lowest) lowest = expected, target_ = id;
    }
    return target_.has_value();
  }

  Vec2 Parking() const { return motes_.at(*target_).last.position + park_offset_; }

  // Towards `goal`: turn towards it, then drive, slowing near it. True once there.
  bool Drive(Node& node, const Pose2D& pose, Vec2 goal) {
    const Vec2 to = goal - pose.position();
    const double distance = Norm(to);
    if (distance < kArrived) {
      node.Drive({0, 0, 0});
      return true;
    }
    const double error = WrapAngle(std::atan2(to.y, to.x) - pose.theta);
    const double forward = std::abs(error) < 0.3 ? std::min(speed_, distance) * std::cos(error) : 0;
    node.Drive({forward, 0, std::clamp(2 * error, -1.5, 1.5)});
    return false;
  }

  static constexpr double kArrived = 0.05;  // m
  Vec2 dock_, park_offset_;
  double threshold_, full_, self_low_, self_full_, urgent_, speed_, max_charge_s_;
  bool visits_;
  State state_ = State::kDocked;
  bool self_charging_ = false;
  double since_ = 0;
  std::optional<NodeId> target_;
  std::map<NodeId, MoteState> motes_;
};

}  // namespace

ControllerInfo ChargerRobotInfo() {
  return {
      "charger_robot",
      "keeps motes alive: from their battery reports it drives to the mote expected lowest (below "
      "`threshold`), parks at `park_offset` from it while its wireless charger charges it to `full`, returns to "
      "`dock` to charge itself below `self_low` (leaving early for a mote below `urgent`); `visits: false` keeps it "
      "docked; metrics visits, charge_s, "
      "reports, docked",
      [](const Params& p) { return std::make_unique<ChargerRobot>(p); }};
}

}  // namespace sanet::controllers
