// A data mule's robot: it tours as `tour` does (points, order, loop, speed, tolerance, ...),
// broadcasts a beacon every `beacon_interval` s on the way, and acknowledges every reading it
// receives. Metrics: `delivered` (1 per reading first received) and `delay` (s from the
// reading's making to its arrival), and at the end (Finish) `motes_heard`.
//
// With `sink: NAME` it also carries the readings on to that base station (a robot with two
// radios hears motes on one and the base on the other): it keeps each new reading until the
// sink acknowledges it, and on each of the sink's beacons sends it up to `batch` of them. Metric
// at the end: `held_at_end`, the readings the sink never acknowledged.
#include <algorithm>
#include <deque>
#include <memory>
#include <set>
#include <stdexcept>
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
        beacon_size_(p.Integer("beacon_size", 16, 1, 60000)),
        sink_name_(p.Text("sink", "")),
        batch_(p.Integer("batch", 20, 1)),
        size_(p.Integer("size", 40, 17, 60000)) {}

  void Start(Node& node) override {
    tour_->Start(node);
    if (sink_name_.empty()) return;
    sink_ = node.Lookup(sink_name_);
    if (!sink_) throw std::runtime_error("data_mule_collector: no node named '" + sink_name_ + "' (parameter 'sink')");
  }

  void ControlStep(Node& node) override {
    tour_->ControlStep(node);
    if (node.Now() < next_beacon_) return;
    next_beacon_ = node.Now() + beacon_interval_;
    node.Broadcast(data_mule::BeaconMessage(beacon_size_));
  }

  void OnMessage(Node& node, const Message& m) override {
    if (sink_ && m.from == *sink_) return FromSink(node, m);
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
    if (sink_) held_.push_back({static_cast<std::uint32_t>(m.from), {number, created}});
  }

  void Finish(Node& node) override {
    node.Metric("motes_heard", static_cast<double>(heard_.size()));
    if (sink_) node.Metric("held_at_end", static_cast<double>(held_.size()));
  }

 private:
  // The sink's beacon asks for what the robot holds; its acknowledgement lets the robot forget.
  void FromSink(Node& node, const Message& m) {
    Reader r(m.payload);
    const auto kind = r.U8();
    if (kind == data_mule::kBeacon) {
      const std::size_t n = std::min<std::size_t>(held_.size(), static_cast<std::size_t>(batch_));
      for (std::size_t i = 0; i < n; ++i) node.Send(*sink_, data_mule::RelayedMessage(held_[i], size_));
      return;
    }
    if (kind != data_mule::kRelayedAck) return;
    const std::uint32_t mote = r.U32(), number = r.U32();
    if (!r.ok()) return;
    held_.erase(
        std::remove_if(held_.begin(), held_.end(),
                       [&](const data_mule::Relayed& h) { return h.mote == mote && h.reading.number == number; }),
        held_.end());
  }

  std::unique_ptr<Controller> tour_;
  double beacon_interval_;
  int beacon_size_;
  std::string sink_name_;
  int batch_, size_;
  std::optional<NodeId> sink_;
  std::deque<data_mule::Relayed> held_;  // for the sink
  double next_beacon_ = 0;
  std::set<std::pair<NodeId, std::uint32_t>> received_;
  std::set<NodeId> heard_;
};

}  // namespace

ControllerInfo DataMuleCollectorInfo() {
  return {"data_mule_collector",
          "a data mule's robot: tours as `tour` does, broadcasts a beacon of `beacon_size` bytes every "
          "`beacon_interval` s, acknowledges each reading; metrics delivered, delay, motes_heard. With `sink`, "
          "carries the readings on to that base station: up to `batch` per sink beacon, of `size` bytes, each "
          "until the sink acknowledges it (metric held_at_end)",
          [](const Params& p) { return std::make_unique<DataMuleCollector>(p); }};
}

}  // namespace sanet::controllers
