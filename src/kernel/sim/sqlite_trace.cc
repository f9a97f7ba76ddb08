#include "sim/sqlite_trace.h"

#include <cstdio>

#include "core/delivery.h"
#include "core/wall_timer.h"

namespace sanet::sim {
namespace {

std::string Number(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

void WriteMessage(trace::RunTrace& db, const Message& m, NodeId to, bool delivered) {
  db.Message(m.time_sent, delivered ? std::optional(m.time_received) : std::nullopt, m.from, to,
             DeliveryName(m.delivery), static_cast<std::uint32_t>(m.payload.size()), delivered ? m.hops : std::nullopt);
}

}  // namespace

SqliteTrace::SqliteTrace(const RunSpec& spec, const RunNodes& nodes, RunBus& bus, trace::ResultsFolder& folder)
    : nodes_(nodes), db_(folder.TempFile("trace.sqlite")) {
  Describe(spec);
  Subscribe(bus);
}

void SqliteTrace::Describe(const RunSpec& spec) {
  db_.Info("format", "sanet trace 1");
  db_.Info("name", spec.name);
  db_.Info("seed", std::to_string(spec.seed));
  db_.Info("duration_s", Number(spec.duration));
  db_.Info("world_size_m", Number(spec.world_size.x) + " " + Number(spec.world_size.y));
  db_.Info("pose_interval_s", Number(spec.trajectory_interval));
  db_.Info("network", spec.network ? "ns-3" : "none");
  for (NodeId id = 0; id < nodes_.size(); ++id) {
    const NodeSpec& n = nodes_[id];
    db_.Node(id, n.name, robots::ModelName(n.model.kind), n.pose.x, n.pose.y, n.pose.theta);
  }
  for (const Obstacle& o : spec.obstacles)
    db_.Obstacle(o.kind, o.box.center.x, o.box.center.y, o.box.size.x, o.box.size.y, o.box.size.z, o.box.yaw);
}

// Subscribes `write` to events of one kind, adding its wall time to the file's (the benchmark
// compares the two trace files' costs).
template <typename Event, typename Write>
void SqliteTrace::Record(RunBus& bus, Write write) {
  subscriptions_.push_back(bus.On<Event>(RunStage::kRecord, [this, write](const Event& e) {
    WallTimer timer(seconds_);
    write(e);
  }));
}

void SqliteTrace::Subscribe(RunBus& bus) {
  Record<NodeSpawned>(bus, [this](const NodeSpawned& e) {
    const Pose2D& p = e.pose;
    db_.Node(e.node, nodes_.NameOf(e.node), robots::ModelName(nodes_[e.node].model.kind), p.x, p.y, p.theta);
    db_.Event(e.t, e.node, "spawn", e.spawned_as);
  });
  Record<PoseRow>(bus, [this](const PoseRow& e) { db_.Pose(e.t, e.node, e.pose.x, e.pose.y, e.pose.theta); });
  Record<net::FrameEvent>(
      bus, [this](const net::FrameEvent& f) { db_.Frame(f.t, f.node, f.sent, f.peer, f.kind, f.bytes); });
  Record<RouteChange>(bus,
                      [this](const RouteChange& r) { db_.Route(r.time, r.node, r.destination, r.next_hop, r.hops); });
  Record<MessageDelivered>(bus, [this](const MessageDelivered& e) { WriteMessage(db_, e.message, e.to, true); });
  Record<MessageLost>(bus, [this](const MessageLost& e) { WriteMessage(db_, e.message, e.to, false); });
  Record<Transitioned>(bus, [this](const Transitioned& e) { db_.Transition(e.t, e.node, e.from, e.to, e.why); });
  Record<MetricReported>(bus, [this](const MetricReported& e) { db_.Metric(e.t, e.node, e.name, e.value); });
  Record<LogLine>(bus, [this](const LogLine& e) { db_.Event(e.t, e.node, "log", e.text); });
  Record<SwitchedOff>(bus, [this](const SwitchedOff& e) { db_.Event(e.t, e.node, "switch_off", ""); });
  Record<Died>(bus, [this](const Died& e) { db_.Event(e.t, e.node, "death", ""); });
  Record<Revived>(bus, [this](const Revived& e) { db_.Event(e.t, e.node, "revival", ""); });
  Record<EnergySampled>(bus, [this](const EnergySampled& e) {
    for (const EnergyLevel& l : e.levels)
      db_.Energy(e.t, l.node, l.battery.remaining_j, l.battery.fraction, l.battery.power_w);
  });
}

void SqliteTrace::Close() {
  subscriptions_.clear();
  WallTimer timer(seconds_);
  db_.Close();
}

}  // namespace sanet::sim
