// A controller library for tests: `crash_after` drives forward and then ends its process the way
// a broken plugin would (`how`: segfault, abort or exit; or throws, `how: throw`) after `after` seconds; `wander`
// drives with the node's random numbers, logs, reports a metric and reads its sensors, so that a run with and without
// isolation can be compared byte for byte; `nan_driver` gives its node commands that are not numbers during its first
// second, between ones that are (the Node contract); `network_probe` logs its node's network view at every step;
// `api_probe` uses what controller API 6 added (Node::Sensor, SetRadioSleep, Controller::Finish).
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "sanet/plugin.h"

namespace {

class CrashAfter : public sanet::Controller {
 public:
  explicit CrashAfter(const sanet::Params& p) : after_(p.Number("after", 1.0)), how_(p.Text("how", "segfault")) {}
  void ControlStep(sanet::Node& node) override {
    node.Drive({0.2, 0, 0});
    if (node.Now() < after_) return;
    if (how_ == "abort") std::abort();
    if (how_ == "exit") std::exit(3);
    if (how_ == "throw") throw std::runtime_error("crash_after: thrown at " + std::to_string(node.Now()) + " s");
    std::raise(SIGSEGV);
  }

 private:
  double after_;
  std::string how_;
};

class Wander : public sanet::Controller {
 public:
  void Start(sanet::Node& node) override { node.Log("wandering from " + node.Name()); }
  void ControlStep(sanet::Node& node) override {
    node.Drive({0.3 * node.Random(), 0, node.Random() - 0.5});
    if (const auto pose = node.GroundTruth()) node.Metric("x", pose->x);
    if (const auto scan = node.Laser()) node.Metric("nearest", scan->ranges.empty() ? 0 : scan->ranges[0]);
    node.Broadcast({static_cast<std::uint8_t>(node.Id())});
  }
  void OnMessage(sanet::Node& node, const sanet::Message& m) override {
    node.Transition("listening", "heard " + node.NameOf(m.from), "a broadcast");
  }
};

class NanDriver : public sanet::Controller {
 public:
  void ControlStep(sanet::Node& node) override {
    if (node.Now() < 1) {
      const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
      const bool drive = node.Drive({0.2, 0, nan});
      const bool wheels = node.SetWheelSpeeds({inf, 1});
      node.Metric("non_finite_taken", (drive ? 1 : 0) + (wheels ? 1 : 0));
    }
    node.Metric("finite_taken", node.Drive({0.3, 0, 0}) ? 1 : 0);
  }
};

// Logs its network view at every step: "net PROTOCOL routes D>N/H/V ... neighbours A,B", after
// sending a byte to `towards` at every step (its route discovery); at `invalidate_at` s it drops
// its route there and logs what InvalidateRoute said, and the view just after.
class NetworkProbe : public sanet::Controller {
 public:
  explicit NetworkProbe(const sanet::Params& p)
      : towards_(p.Text("towards", "")), invalidate_at_(p.Number("invalidate_at", -1)) {}
  void ControlStep(sanet::Node& node) override {
    const auto target = node.Lookup(towards_);
    if (target) node.Send(*target, {1});
    if (target && invalidate_at_ >= 0 && node.Now() >= invalidate_at_) {
      invalidate_at_ = -1;
      node.Log(std::string("invalidated ") + (node.Network().InvalidateRoute(*target) ? "true" : "false"));
    }
    node.Log(View(node));
  }

 private:
  static std::string View(sanet::Node& node) {
    sanet::NetworkView& net = node.Network();
    std::string line = "net " + net.Protocol() + " routes";
    for (const sanet::RouteEntry& r : net.RoutingTable())
      line += " " + node.NameOf(r.destination) + ">" + node.NameOf(r.next_hop) + "/" + std::to_string(r.hops) + "/" +
              (r.valid ? "1" : "0");
    line += " neighbours ";
    std::string names;
    for (sanet::NodeId n : net.Neighbours()) names += (names.empty() ? "" : ",") + node.NameOf(n);
    return line + names;
  }
  std::string towards_;
  double invalidate_at_;
};

// Reads a named sensor instance, one that does not exist and the ground truth through
// Node::Sensor; puts its radio to sleep from `sleep_from` to `sleep_to` s (metrics sleep_taken,
// wake_taken); broadcasts at every step and records each message it hears (metric
// heard_<sender>, valued the time it heard it); in Finish, how many it heard (finished_heard).
class ApiProbe : public sanet::Controller {
 public:
  explicit ApiProbe(const sanet::Params& p)
      : sleep_from_(p.Number("sleep_from", -1)), sleep_to_(p.Number("sleep_to", -1)) {}
  void Start(sanet::Node& node) override {
    const auto rear = node.SensorAs<sanet::RangeScan>("laser_rear");
    node.Metric("rear_beams", rear ? static_cast<double>(rear->ranges.size()) : -1);
    node.Metric("unknown_sensor", node.Sensor("no_such_sensor") ? 1 : 0);
    node.Metric("truth_is_pose", node.SensorAs<sanet::Pose2D>("ground_truth") ? 1 : 0);
    const auto ring = node.SensorAs<sanet::RangeScan>("ir2");  // a named ring whose name ends in a digit
    node.Metric("ir2_sensors", ring ? static_cast<double>(ring->ranges.size()) : -1);
    const auto sonar = node.SensorAs<sanet::RangeScan>("sonar");
    node.Metric("sonar_range", sonar ? sonar->ranges.at(0) : -1);
  }
  void ControlStep(sanet::Node& node) override {
    if (sleep_from_ >= 0 && state_ == 0 && node.Now() >= sleep_from_) {
      state_ = 1;
      node.Metric("sleep_taken", node.SetRadioSleep(true) ? 1 : 0);
    }
    if (state_ == 1 && node.Now() >= sleep_to_) {
      state_ = 2;
      node.Metric("wake_taken", node.SetRadioSleep(false) ? 1 : 0);
    }
    node.Broadcast({1});
  }
  void OnMessage(sanet::Node& node, const sanet::Message& m) override {
    node.Metric("heard_" + node.NameOf(m.from), node.Now());
    ++heard_;
  }
  void Finish(sanet::Node& node) override {
    node.Metric("finished_heard", heard_);
    node.Log("finished at " + std::to_string(node.Now()));
  }

 private:
  double sleep_from_, sleep_to_;
  int state_ = 0;  // 0 awake, 1 asleep, 2 woken
  int heard_ = 0;
};

}  // namespace

SANET_CONTROLLER_PLUGIN(registry) {
  registry.Add({"api_probe", "uses Node::Sensor, SetRadioSleep and Controller::Finish",
                [](const sanet::Params& p) { return std::make_unique<ApiProbe>(p); }});
  registry.Add({"crash_after", "drives, then crashes its process",
                [](const sanet::Params& p) { return std::make_unique<CrashAfter>(p); }});
  registry.Add({"nan_driver", "gives its node commands that are not numbers, between ones that are",
                [](const sanet::Params&) { return std::make_unique<NanDriver>(); }});
  registry.Add({"network_probe", "logs its network view at every step, sending to `towards`",
                [](const sanet::Params& p) { return std::make_unique<NetworkProbe>(p); }});
  registry.Add({"wander", "drives at random, logs, reports and broadcasts",
                [](const sanet::Params&) { return std::make_unique<Wander>(); }});
}
