// A data mule's base station: it broadcasts a beacon every `beacon_interval` s and acknowledges
// every reading a robot relays to it (the robot's `sink` parameter names it). Metrics:
// `delivered` (1 per reading first received, whichever robot brought it) and `delay` (s from the
// reading's making at its mote to its arrival here), and at the end `motes_heard`.
#include <memory>
#include <set>

#include "controllers.h"
#include "data_mule/messages.h"

namespace sanet::controllers {
namespace {

class DataMuleSink : public Controller {
 public:
  explicit DataMuleSink(const Params& p)
      : beacon_interval_(p.Number("beacon_interval", 1, 0.01)), beacon_size_(p.Integer("beacon_size", 16, 1, 60000)) {}

  void ControlStep(Node& node) override {
    if (node.Now() < next_beacon_) return;
    next_beacon_ = node.Now() + beacon_interval_;
    node.Broadcast(data_mule::BeaconMessage(beacon_size_));
  }

  void OnMessage(Node& node, const Message& m) override {
    Reader r(m.payload);
    if (r.U8() != data_mule::kRelayed) return;
    const std::uint32_t mote = r.U32(), number = r.U32();
    const double created = r.F64();
    if (!r.ok()) return;
    node.Send(m.from, data_mule::RelayedAckMessage(mote, number));  // again if the last was lost
    if (!received_.insert({mote, number}).second) return;
    node.Metric("delivered", 1);
    node.Metric("delay", node.Now() - created);
    motes_.insert(mote);
  }

  void Finish(Node& node) override { node.Metric("motes_heard", static_cast<double>(motes_.size())); }

 private:
  double beacon_interval_;
  int beacon_size_;
  double next_beacon_ = 0;
  std::set<std::pair<std::uint32_t, std::uint32_t>> received_;  // (mote, number)
  std::set<std::uint32_t> motes_;
};

}  // namespace

ControllerInfo DataMuleSinkInfo() {
  return {"data_mule_sink",
          "a data mule's base station: broadcasts a beacon of `beacon_size` bytes every `beacon_interval` s and "
          "acknowledges each reading a robot relays; metrics delivered, delay (from the reading's making), "
          "motes_heard",
          [](const Params& p) { return std::make_unique<DataMuleSink>(p); }};
}

}  // namespace sanet::controllers
