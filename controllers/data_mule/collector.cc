// A data mule's robot: it tours as `tour` does (points, order, loop, speed, tolerance, ...),
// broadcasts a beacon every `beacon_interval` s on the way, and acknowledges every reading it
// receives. Metrics: `delivered` (1 per reading first received) and `delay` (s from the
// reading's making to its arrival), and at the end (Finish) `motes_heard`.
#include <memory>
#include <set>
#include <utility>

#include "controllers.h"
#include "data_mule/messages.h"
#include "mobility.h"

namespace sanet::controllers {
namespace {

class DataMuleCollector : public Controller {
 public:
  explicit DataMuleCollector(const Params& p)
      : tour_(MakeTour(p)),
        beacon_interval_(p.Number("beacon_interval", 1, 0.01)),
        beacon_size_(p.Integer("beacon_size", 16, 1, 60000)) {}

  void ControlStep(Node& node) override {
    tour_->ControlStep(node);
    if (node.Now() < next_beacon_) return;
    next_beacon_ = node.Now() + beacon_interval_;
    Bytes beacon = Writer().U8(data_mule::kBeacon).bytes();
    beacon.resize(beacon_size_, 0);
    node.Broadcast(beacon);
  }

  void OnMessage(Node& node, const Message& m) override {
    Reader r(m.payload);
    if (r.U8() != data_mule::kReading) return;
    const std::uint32_t number = r.U32();
    const double created = r.F64();
    if (!r.ok()) return;
    node.Send(m.from, data_mule::AckMessage(number));  // again if the last ack was lost
    if (!received_.insert({m.from, number}).second) return;
    node.Metric("delivered", 1);
    node.Metric("delay", node.Now() - created);
    heard_.insert(m.from);
  }

  void Finish(Node& node) override { node.Metric("motes_heard", static_cast<double>(heard_.size())); }

 private:
  std::unique_ptr<Controller> tour_;
  double beacon_interval_;
  int beacon_size_;
  double next_beacon_ = 0;
  std::set<std::pair<NodeId, std::uint32_t>> received_;
  std::set<NodeId> heard_;
};

}  // namespace

ControllerInfo DataMuleCollectorInfo() {
  return {"data_mule_collector",
          "a data mule's robot: tours as `tour` does, broadcasts a beacon of `beacon_size` bytes every "
          "`beacon_interval` s, acknowledges each reading; metrics delivered, delay, motes_heard",
          [](const Params& p) { return std::make_unique<DataMuleCollector>(p); }};
}

}  // namespace sanet::controllers
