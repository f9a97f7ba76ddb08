// A data mule's mote (Shah et al., "Data MULEs: modeling a three-tier architecture for sparse
// sensor networks", SNPA 2003): it makes a reading every `interval` s and keeps up to `buffer` of
// them (the oldest dropped when full); when it hears the robot's beacon it sends the robot what
// it holds, at most `batch` readings per beacon, and forgets a reading once the robot acknowledges
// it. Metrics: `created` (1 per reading) and, at the end (Finish), `held_at_end` (what it still
// holds) and `overflowed` (readings dropped from a full buffer), both reported even when 0 so
// that every run has them.
#include <algorithm>
#include <deque>
#include <memory>
#include <stdexcept>

#include "controllers.h"
#include "data_mule/messages.h"

namespace sanet::controllers {
namespace {

using data_mule::Reading;

class DataMuleSensor : public Controller {
 public:
  explicit DataMuleSensor(const Params& p)
      : mule_(p.Text("mule", "mule")),
        interval_(p.Number("interval", 10, 0.01)),
        size_(p.Integer("size", 32, 13, 60000)),
        buffer_(p.Integer("buffer", 1000, 1)),
        batch_(p.Integer("batch", 20, 1)) {}

  void Start(Node& node) override {
    robot_ = node.Lookup(mule_);
    if (!robot_) throw std::runtime_error("data_mule_sensor: no node named '" + mule_ + "' (parameter 'mule')");
    next_ = interval_ * node.Random();  // motes out of step, as motes switched on by hand are
  }

  // Every reading due by now, even several in one control step (an interval under the step's).
  void ControlStep(Node& node) override {
    for (; node.Now() >= next_; next_ += interval_) {
      if (static_cast<int>(held_.size()) >= buffer_) {
        held_.pop_front();
        ++overflowed_;
      }
      held_.push_back({made_++, node.Now()});
      node.Metric("created", 1);
    }
  }

  void OnMessage(Node& node, const Message& m) override {
    if (m.from != *robot_) return;
    Reader r(m.payload);
    const auto kind = r.U8();
    if (kind == data_mule::kBeacon) {
      int sent = 0;
      for (const Reading& reading : held_)
        if (sent++ < batch_) node.Send(*robot_, data_mule::ReadingMessage(reading, size_));
    } else if (kind == data_mule::kAck) {
      const std::uint32_t number = r.U32();
      if (!r.ok()) return;
      held_.erase(std::remove_if(held_.begin(), held_.end(), [number](const Reading& h) { return h.number == number; }),
                  held_.end());
    }
  }

  void Finish(Node& node) override {
    node.Metric("held_at_end", static_cast<double>(held_.size()));
    node.Metric("overflowed", static_cast<double>(overflowed_));
  }

 private:
  std::string mule_;
  double interval_;
  int size_, buffer_, batch_;
  std::optional<NodeId> robot_;
  std::deque<Reading> held_;
  std::uint32_t made_ = 0, overflowed_ = 0;
  double next_ = 0;
};

}  // namespace

ControllerInfo DataMuleSensorInfo() {
  return {"data_mule_sensor",
          "a data mule's mote: a reading every `interval` s, kept (at most `buffer`) until the robot `mule` "
          "acknowledges it; on the robot's beacon sends up to `batch` readings of `size` bytes; metrics created, "
          "and at the end held_at_end and overflowed",
          [](const Params& p) { return std::make_unique<DataMuleSensor>(p); }};
}

}  // namespace sanet::controllers
