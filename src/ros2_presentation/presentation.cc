#include "ros2_presentation/presentation.h"

#include <chrono>

#include "sim/assembly.h"
#include "sim/world.h"

namespace sanet::sim {

// trace.mcap: the messages' MCAP sink, closed (the radio's last window sent first) with the results.
class Ros2Presentation::McapFileOf : public TraceFile {
 public:
  McapFileOf(Ros2Presentation& presentation, const std::string& path) : presentation_(presentation), sink_(path) {
    presentation_.AddSink(sink_);
  }
  void Close() override {
    const auto start = std::chrono::steady_clock::now();
    presentation_.subscriptions_.clear();
    presentation_.messages_.Flush();
    sink_.Close();
    presentation_.seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  void Report(nlohmann::ordered_json& trace_profile, std::vector<std::string>& warnings) const override {
    trace_profile["mcap"] = presentation_.seconds_;
    if (sink_.left_out() > 0)
      warnings.push_back("trace.mcap holds its first 65535 topics (MCAP numbers channels with 16 bits); " +
                         std::to_string(sink_.left_out()) + " more were left out of it");
  }

 private:
  Ros2Presentation& presentation_;
  McapSink sink_;
};

Ros2Presentation::Ros2Presentation(World& world)
    : bus_(world.bus()), messages_(world.spec(), world.parts().run_nodes()) {}

MakeTraceFile Ros2Presentation::McapFile() {
  return [this](const TraceFileContext& run) -> std::unique_ptr<TraceFile> {
    return std::make_unique<McapFileOf>(*this, run.folder.TempFile("trace.mcap"));
  };
}

void Ros2Presentation::AddSink(MessageSink& sink) {
  if (subscriptions_.empty()) Subscribe();
  messages_.AddSink(sink);
}

// Subscribes `present` to events of one kind, adding its wall time to the presentation's.
template <typename Event, typename Make>
void Ros2Presentation::Present(Make make) {
  subscriptions_.push_back(bus_.On<Event>(RunStage::kRecord, [this, make](const Event& e) {
    const auto start = std::chrono::steady_clock::now();
    make(e);
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }));
}

void Ros2Presentation::Subscribe() {
  RunMessages& m = messages_;
  Present<NodeSpawned>([&m](const NodeSpawned& e) {
    m.Spawned(e.t);
    m.Event(e.t, e.node, "spawn", e.spawned_as);
  });
  Present<PoseRow>([&m](const PoseRow& e) { m.Pose(e.t, e.node, e.pose, e.velocity); });
  Present<SensorRead>([&m](const SensorRead& e) { m.Read(e.t, e.node, e.instance, e.kind, e.reading, e.body); });
  Present<net::FrameEvent>([&m](const net::FrameEvent& f) { m.Frame(f); });
  Present<RouteChange>([&m](const RouteChange& r) { m.Route(r); });
  Present<MessageDelivered>(
      [&m](const MessageDelivered& e) { m.Message(e.message.time_received, e.message, e.to, true); });
  Present<MessageLost>([&m](const MessageLost& e) { m.Message(e.t, e.message, e.to, false); });
  Present<Transitioned>([&m](const Transitioned& e) { m.Transition(e.t, e.node, e.from, e.to, e.why); });
  Present<MetricReported>([&m](const MetricReported& e) { m.Metric(e.t, e.node, e.name, e.value); });
  Present<LogLine>([&m](const LogLine& e) { m.Event(e.t, e.node, "log", e.text); });
  Present<SwitchedOff>([&m](const SwitchedOff& e) { m.Event(e.t, e.node, "switch_off", ""); });
}

}  // namespace sanet::sim
