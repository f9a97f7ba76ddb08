#include "ros2_presentation/presentation.h"

#include "core/wall_timer.h"
#include "sim/world.h"

namespace sanet::ros2_presentation {

// trace.mcap: the messages' MCAP sink, closed (the radio's last window sent first) with the results.
class RunPresentation::McapFileOf : public sim::TraceFile {
 public:
  McapFileOf(RunPresentation& presentation, const std::string& path) : presentation_(presentation), sink_(path) {
    presentation_.AddSink(sink_);
  }
  void Close() override {
    WallTimer timer(presentation_.seconds_);
    presentation_.subscriptions_.clear();
    presentation_.messages_.Flush();
    sink_.Close();
  }
  void Report(nlohmann::ordered_json& trace_profile, std::vector<std::string>& warnings) const override {
    trace_profile["mcap"] = presentation_.seconds_;
    if (sink_.left_out() > 0)
      warnings.push_back("trace.mcap holds its first 65535 topics (MCAP numbers channels with 16 bits); " +
                         std::to_string(sink_.left_out()) + " more were left out of it");
  }

 private:
  RunPresentation& presentation_;
  McapSink sink_;
};

RunPresentation::RunPresentation(sim::World& world) : bus_(world.bus()), messages_(world.spec(), world.nodes()) {}

sim::MakeTraceFile RunPresentation::McapFile() {
  return [this](const sim::TraceFileContext& run) -> std::unique_ptr<sim::TraceFile> {
    return std::make_unique<McapFileOf>(*this, run.folder.TempFile("trace.mcap"));
  };
}

void RunPresentation::AddSink(MessageSink& sink) {
  if (subscriptions_.empty()) Subscribe();
  messages_.AddSink(sink);
}

// Subscribes `present` to events of one kind, adding its wall time to the presentation's.
template <typename Event, typename Make>
void RunPresentation::Present(Make make) {
  subscriptions_.push_back(bus_.On<Event>(sim::RunStage::kRecord, [this, make](const Event& e) {
    WallTimer timer(seconds_);
    make(e);
  }));
}

void RunPresentation::Subscribe() {
  RunMessages& m = messages_;
  Present<sim::NodeSpawned>([&m](const sim::NodeSpawned& e) {
    m.Spawned(e.t);
    m.Event(e.t, e.node, "spawn", e.spawned_as);
  });
  Present<sim::PoseRow>([&m](const sim::PoseRow& e) { m.Pose(e.t, e.node, e.pose, e.velocity, e.wheel_angles); });
  Present<sim::SensorRead>(
      [&m](const sim::SensorRead& e) { m.Read(e.t, e.node, e.instance, e.kind, e.reading, e.body); });
  Present<net::FrameEvent>([&m](const net::FrameEvent& f) { m.Frame(f); });
  Present<sim::RouteChange>([&m](const sim::RouteChange& r) { m.Route(r); });
  Present<sim::MessageDelivered>(
      [&m](const sim::MessageDelivered& e) { m.Message(e.message.time_received, e.message, e.to, true); });
  Present<sim::MessageLost>([&m](const sim::MessageLost& e) { m.Message(e.t, e.message, e.to, false); });
  Present<sim::Transitioned>([&m](const sim::Transitioned& e) { m.Transition(e.t, e.node, e.from, e.to, e.why); });
  Present<sim::MetricReported>([&m](const sim::MetricReported& e) { m.Metric(e.t, e.node, e.name, e.value); });
  Present<sim::LogLine>([&m](const sim::LogLine& e) { m.Event(e.t, e.node, "log", e.text); });
  Present<sim::SwitchedOff>([&m](const sim::SwitchedOff& e) { m.Event(e.t, e.node, "switch_off", ""); });
  Present<sim::Died>([&m](const sim::Died& e) { m.Event(e.t, e.node, "death", ""); });
  Present<sim::Revived>([&m](const sim::Revived& e) { m.Event(e.t, e.node, "revival", ""); });
  Present<sim::EnergySampled>([&m](const sim::EnergySampled& e) {
    for (const sim::EnergyLevel& level : e.levels) m.Battery(e.t, level.node, level.battery);
  });
  Present<sim::RunEnded>([&m](const sim::RunEnded&) { m.Flush(); });  // the last radio window
}

}  // namespace sanet::ros2_presentation
