// A running world as a Foxglove stream (`sanet serve --view`, `sanet run --view`): the run's ROS 2
// messages (ros2_presentation/run_messages.h, the bytes its MCAP log holds) go to the hub as they are made, and
// its simulated time after the physics steps, at most every 50 ms of it.
#pragma once

#include "foxglove/foxglove_hub.h"
#include "ros2_presentation/message_sink.h"
#include "ros2_presentation/presentation.h"
#include "sim/run_events.h"

namespace sanet::foxglove {

class FoxgloveLive : public ros2_presentation::MessageSink {
 public:
  explicit FoxgloveLive(HubSettings settings) : hub_(std::move(settings)) {}
  FoxgloveHub& hub() { return hub_; }

  void Advertise(const ros2_presentation::Topic& topic) override {
    hub_.Advertise({topic.id, topic.name, topic.type, topic.definition, topic.latched});
  }
  void Publish(const ros2_presentation::Topic& topic, std::uint64_t time_ns,
               const std::vector<std::uint8_t>& cdr) override {
    hub_.Publish(topic.id, time_ns, cdr);
  }
  bool Active() const override { return hub_.clients() > 0; }
  // Streams the run's messages (`presentation`) and its time (`bus`) from now on.
  void Observe(sim::RunBus& bus, ros2_presentation::RunPresentation& presentation);
  void AfterStep(const sim::WorldSnapshot& snapshot);

 private:
  FoxgloveHub hub_;
  double last_time_ = -1;  // s, the last time sent
  Subscription step_ended_;
};

}  // namespace sanet::foxglove
