#include "sim/run_traces.h"

#include <chrono>
#include <cstdio>

#include "core/delivery.h"

namespace sanet::sim {
namespace {

// Adds the wall time `write` takes to `total`: the benchmark compares the two writers' costs.
template <typename Write>
void Timed(double& total, Write&& write) {
  const auto start = std::chrono::steady_clock::now();
  write();
  total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string Number(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

}  // namespace

RunTraces::RunTraces(const RunSpec& spec, const RunNodes& nodes, trace::ResultsFolder* folder)
    : nodes_(nodes), messages_(spec, nodes) {
  if (!folder) return;
  sqlite_ = std::make_unique<trace::RunTrace>(folder->TempFile("trace.sqlite"));
  mcap_file_ = std::make_unique<McapSink>(folder->TempFile("trace.mcap"));
  messages_.AddSink(*mcap_file_);
  Describe(spec);
}

void RunTraces::Describe(const RunSpec& spec) {
  sqlite_->Info("format", "sanet trace 1");
  sqlite_->Info("name", spec.name);
  sqlite_->Info("seed", std::to_string(spec.seed));
  sqlite_->Info("duration_s", Number(spec.duration));
  sqlite_->Info("world_size_m", Number(spec.world_size.x) + " " + Number(spec.world_size.y));
  sqlite_->Info("pose_interval_s", Number(spec.trajectory_interval));
  sqlite_->Info("network", spec.network ? "ns-3" : "none");
  for (NodeId id = 0; id < nodes_.size(); ++id) {
    const NodeSpec& n = nodes_[id];
    sqlite_->Node(id, n.name, robots::ModelName(n.model.kind), n.pose.x, n.pose.y, n.pose.theta);
  }
  for (const Obstacle& o : spec.obstacles)
    sqlite_->Obstacle(o.kind, o.box.center.x, o.box.center.y, o.box.size.x, o.box.size.y, o.box.size.z, o.box.yaw);
}

void RunTraces::Spawned(double t, NodeId node, const std::string& spawned_as, const Pose2D& pose) {
  if (sqlite_)
    Timed(sqlite_seconds_, [&] {
      sqlite_->Node(node, nodes_.NameOf(node), robots::ModelName(nodes_[node].model.kind), pose.x, pose.y, pose.theta);
    });
  Timed(mcap_seconds_, [&] { messages_.Spawned(t); });
  Event(t, node, "spawn", spawned_as);
}

void RunTraces::Pose(double t, NodeId node, const Pose2D& pose, const Twist2D& velocity) {
  if (sqlite_) Timed(sqlite_seconds_, [&] { sqlite_->Pose(t, node, pose.x, pose.y, pose.theta); });
  Timed(mcap_seconds_, [&] { messages_.Pose(t, node, pose, velocity); });
}

void RunTraces::Frame(const net::FrameEvent& f) {
  if (sqlite_) Timed(sqlite_seconds_, [&] { sqlite_->Frame(f.t, f.node, f.sent, f.peer, f.kind, f.bytes); });
  Timed(mcap_seconds_, [&] { messages_.Frame(f); });
}

void RunTraces::Route(const RouteChange& r) {
  if (sqlite_) Timed(sqlite_seconds_, [&] { sqlite_->Route(r.time, r.node, r.destination, r.next_hop, r.hops); });
  Timed(mcap_seconds_, [&] { messages_.Route(r); });
}

void RunTraces::Message(double t, const sanet::Message& m, NodeId to, bool delivered) {
  const auto bytes = static_cast<std::uint32_t>(m.payload.size());
  const std::optional<double> received = delivered ? std::optional(m.time_received) : std::nullopt;
  const std::optional<int> hops = delivered ? m.hops : std::nullopt;
  if (sqlite_)
    Timed(sqlite_seconds_,
          [&] { sqlite_->Message(m.time_sent, received, m.from, to, DeliveryName(m.delivery), bytes, hops); });
  Timed(mcap_seconds_, [&] { messages_.Message(t, m, to, delivered); });
}

void RunTraces::Transition(double t, NodeId node, const std::string& from, const std::string& to,
                           const std::string& why) {
  if (sqlite_) Timed(sqlite_seconds_, [&] { sqlite_->Transition(t, node, from, to, why); });
  Timed(mcap_seconds_, [&] { messages_.Transition(t, node, from, to, why); });
}

void RunTraces::Metric(double t, NodeId node, const std::string& name, double value) {
  if (sqlite_) Timed(sqlite_seconds_, [&] { sqlite_->Metric(t, node, name, value); });
  Timed(mcap_seconds_, [&] { messages_.Metric(t, node, name, value); });
}

void RunTraces::Event(double t, NodeId node, const char* kind, const std::string& detail) {
  if (sqlite_) Timed(sqlite_seconds_, [&] { sqlite_->Event(t, node, kind, detail); });
  Timed(mcap_seconds_, [&] { messages_.Event(t, node, kind, detail); });
}

void RunTraces::Read(double t, NodeId node, const std::string& instance, const std::string& kind,
                     const SensorReading& reading, const BodyState& body) {
  Timed(mcap_seconds_, [&] { messages_.Read(t, node, instance, kind, reading, body); });
}

void RunTraces::Close() {
  Timed(mcap_seconds_, [&] {
    messages_.Flush();
    if (mcap_file_) mcap_file_->Close();
  });
  if (sqlite_) Timed(sqlite_seconds_, [&] { sqlite_->Close(); });
}

}  // namespace sanet::sim
