#include "sim/run_traces.h"

#include <cstdio>

#include "core/delivery.h"

namespace sanet::sim {
namespace {

std::string Number(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

}  // namespace

RunTraces::RunTraces(const RunSpec& spec, const RunNodes& nodes, trace::ResultsFolder& folder)
    : nodes_(nodes),
      sqlite_(folder.TempFile("trace.sqlite")),
      mcap_(folder.TempFile("trace.mcap"), spec, nodes) {
  Describe(spec);
}

void RunTraces::Describe(const RunSpec& spec) {
  sqlite_.Info("format", "sanet trace 1");
  sqlite_.Info("name", spec.name);
  sqlite_.Info("seed", std::to_string(spec.seed));
  sqlite_.Info("duration_s", Number(spec.duration));
  sqlite_.Info("world_size_m", Number(spec.world_size.x) + " " + Number(spec.world_size.y));
  sqlite_.Info("pose_interval_s", Number(spec.trajectory_interval));
  sqlite_.Info("network", spec.network ? "ns-3" : "none");
  for (NodeId id = 0; id < nodes_.size(); ++id) {
    const NodeSpec& n = nodes_[id];
    sqlite_.Node(id, n.name, robots::ModelName(n.model.kind), n.pose.x, n.pose.y, n.pose.theta);
  }
  for (const Obstacle& o : spec.obstacles)
    sqlite_.Obstacle(o.kind, o.box.center.x, o.box.center.y, o.box.size.x, o.box.size.y, o.box.size.z, o.box.yaw);
}

void RunTraces::Spawned(double t, NodeId node, const std::string& spawned_as, const Pose2D& pose) {
  sqlite_.Node(node, nodes_.NameOf(node), robots::ModelName(nodes_[node].model.kind), pose.x, pose.y, pose.theta);
  mcap_.Spawned(t);
  Event(t, node, "spawn", spawned_as);
}

void RunTraces::Pose(double t, NodeId node, const Pose2D& pose, const Twist2D& velocity) {
  sqlite_.Pose(t, node, pose.x, pose.y, pose.theta);
  mcap_.Pose(t, node, pose, velocity);
}

void RunTraces::Frame(const net::FrameEvent& f) {
  sqlite_.Frame(f.t, f.node, f.sent, f.peer, f.kind, f.bytes);
  mcap_.Frame(f);
}

void RunTraces::Route(const RouteChange& r) {
  sqlite_.Route(r.time, r.node, r.destination, r.next_hop, r.hops);
  mcap_.Route(r);
}

void RunTraces::Message(double t, const sanet::Message& m, NodeId to, bool delivered) {
  const auto bytes = static_cast<std::uint32_t>(m.payload.size());
  if (delivered)
    sqlite_.Message(m.time_sent, m.time_received, m.from, to, DeliveryName(m.delivery), bytes, m.hops);
  else
    sqlite_.Message(m.time_sent, std::nullopt, m.from, to, DeliveryName(m.delivery), bytes, std::nullopt);
  mcap_.Message(t, m, to, delivered);
}

void RunTraces::Transition(double t, NodeId node, const std::string& from, const std::string& to,
                           const std::string& why) {
  sqlite_.Transition(t, node, from, to, why);
  mcap_.Transition(t, node, from, to, why);
}

void RunTraces::Metric(double t, NodeId node, const std::string& name, double value) {
  sqlite_.Metric(t, node, name, value);
  mcap_.Metric(t, node, name, value);
}

void RunTraces::Event(double t, NodeId node, const char* kind, const std::string& detail) {
  sqlite_.Event(t, node, kind, detail);
  mcap_.Event(t, node, kind, detail);
}

void RunTraces::Close() {
  sqlite_.Close();
  mcap_.Close();
}

}  // namespace sanet::sim
