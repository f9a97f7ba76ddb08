// The run as ROS 2 messages (RunMessages), made from its events on the bus, for trace.mcap and
// for live sinks (a Foxglove stream). Whoever runs the run attaches it: nothing is made, and no
// event is heard, until it has a sink. One per run, kept until the run is finished.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "ros2_presentation/mcap_sink.h"
#include "ros2_presentation/message_sink.h"
#include "ros2_presentation/run_messages.h"
#include "sim/run_events.h"
#include "sim/trace_file.h"

namespace sanet::sim {
class World;
}  // namespace sanet::sim

namespace sanet::ros2_presentation {

class RunPresentation {
 public:
  explicit RunPresentation(sim::World& world);
  // trace.mcap, when the run writes a trace (a trace file for RunOptions::trace_files).
  sim::MakeTraceFile McapFile();
  // A live sink, added before the run starts.
  void AddSink(MessageSink& sink);

 private:
  class McapFileOf;
  void Subscribe();
  template <typename Event, typename Make>
  void Present(Make make);

  sim::RunBus& bus_;
  RunMessages messages_;
  std::vector<Subscription> subscriptions_;
  double seconds_ = 0;  // wall time spent making the messages and writing trace.mcap
};

}  // namespace sanet::ros2_presentation
