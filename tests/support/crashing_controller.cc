// A controller library for tests: `crash_after` drives forward and then ends its process the way
// a broken plugin would (`how`: segfault, abort or exit) after `after` seconds; `wander` drives
// with the node's random numbers, logs, reports a metric and reads its sensors, so that a run
// with and without isolation can be compared byte for byte; `nan_driver` gives its node commands
// that are not numbers during its first second, between ones that are (the Node contract).
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <limits>
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

}  // namespace

SANET_CONTROLLER_PLUGIN(registry) {
  registry.Add({"crash_after", "drives, then crashes its process",
                [](const sanet::Params& p) { return std::make_unique<CrashAfter>(p); }});
  registry.Add({"nan_driver", "gives its node commands that are not numbers, between ones that are",
                [](const sanet::Params&) { return std::make_unique<NanDriver>(); }});
  registry.Add({"wander", "drives at random, logs, reports and broadcasts",
                [](const sanet::Params&) { return std::make_unique<Wander>(); }});
}
