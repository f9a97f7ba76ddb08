// Sends a message of `size` bytes every `interval` seconds from `start` to `stop`: to one node
// (`to: name`), to the neighbours (`to: broadcast`) or to the whole network (`to: flood`).
// Traffic for trying networks; what arrives is in the run's messages.csv.
#include <cmath>
#include <memory>
#include <stdexcept>

#include "controllers.h"
#include "sanet/codec.h"

namespace sanet::controllers {
namespace {

class Pinger : public Controller {
 public:
  explicit Pinger(const Params& p)
      : to_(p.Text("to", "broadcast")),
        interval_(p.Number("interval", 1, 0.001)),
        start_(p.Number("start", 1, 0)),
        stop_(p.Number("stop", HUGE_VAL, 0)),
        size_(p.Integer("size", 16, 4, 60000)) {}

  void Start(Node& node) override {
    if (to_ != "broadcast" && to_ != "flood") {
      target_ = node.Lookup(to_);
      if (!target_) throw std::runtime_error("pinger: no node named '" + to_ + "'");
    }
  }

  void ControlStep(Node& node) override {
    const double t = node.Now();
    if (t < start_ || t > stop_ || t < next_) return;
    next_ = std::max(next_, start_) + interval_;
    Bytes payload = Writer().U32(count_++).bytes();
    payload.resize(size_, 0);
    if (target_)
      node.Send(*target_, payload);
    else if (to_ == "flood")
      node.Flood(payload);
    else
      node.Broadcast(payload);
  }

 private:
  std::string to_;
  double interval_, start_, stop_;
  int size_;
  std::optional<NodeId> target_;
  double next_ = 0;
  std::uint32_t count_ = 0;
};

}  // namespace

ControllerInfo PingerInfo() {
  return {"pinger",
          "sends `size` bytes every `interval` s from `start` to `stop` to node `to`, or to "
          "`broadcast` (neighbours) or `flood` (whole network)",
          [](const Params& p) { return std::make_unique<Pinger>(p); }};
}

}  // namespace sanet::controllers
