#include "sim/outputs.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "core/delivery.h"
#include "core/statistics.h"
#include "trace/result_headers.h"

namespace sanet::sim {
namespace {

std::string Format(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string Format(const char* format, ...) {
  char line[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  return line;
}

// printf's "%.6f" through std::to_chars, which the standard defines as printf's text, without
// parsing a format: messages.csv gets a row per delivered message, 10^4 a second in a swarm.
void AppendFixed6(std::string& out, double value) {
  char text[64];
  const std::to_chars_result end = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, 6);
  out.append(text, end.ptr);
}

bool Unmoved(const Pose2D& p, const Pose2D& last) {
  return std::fabs(p.x - last.x) < 5e-5 && std::fabs(p.y - last.y) < 5e-5 &&
         std::fabs(WrapAngle(p.theta - last.theta)) < 5e-5;
}

}  // namespace

Outputs::Outputs(const RunSpec& spec, const RunNodes& nodes, RunBus& bus, const std::string& dir, bool force,
                 const std::vector<MakeTraceFile>& trace_files)
    : spec_(spec),
      nodes_(nodes),
      bus_(bus),
      folder_(dir, force),
      trajectories_(folder_.Csv("trajectories.csv", "time,node,x,y,theta")),
      log_(folder_.Csv("log.csv", trace::kLogHeader)),
      messages_(folder_.Csv("messages.csv", trace::kMessagesHeader)),
      transitions_(folder_.Csv("transitions.csv", trace::kTransitionsHeader)),
      metric_rows_(folder_.Csv("metrics.csv", trace::kMetricsHeader)),
      energy_(nodes, bus, folder_),
      radio_contacts_(spec, nodes, bus, folder_),
      last_recorded_(nodes.size()) {
  if (spec_.min_distance) min_distance_ = &folder_.Csv("min_distance.csv", "time,min_distance,a,b");
  StartTrace(trace_files);
  Subscribe();
}

void Outputs::StartTrace(const std::vector<MakeTraceFile>& trace_files) {
  if (!spec_.trace || !folder_.writes()) return;
  sqlite_ = std::make_unique<SqliteTrace>(spec_, nodes_, bus_, folder_);
  for (const MakeTraceFile& make : trace_files)
    if (auto file = make(TraceFileContext{spec_, nodes_, bus_, folder_})) trace_files_.push_back(std::move(file));
}

template <typename Event, typename Handler>
void Outputs::Hear(Handler handler) {
  subscriptions_.push_back(bus_.On<Event>(RunStage::kRecord, std::move(handler)));
}

void Outputs::Subscribe() {
  Hear<LogLine>([this](const LogLine& e) { Log(e); });
  Hear<Transitioned>([this](const Transitioned& e) { Transition(e); });
  Hear<MetricReported>([this](const MetricReported& e) { Metric(e); });
  Hear<MessageDelivered>([this](const MessageDelivered& e) { Delivered(e); });
  Hear<MessageDropped>([this](const MessageDropped&) { ++messages_lost_; });
  Hear<MessageLost>([this](const MessageLost& e) { Lost(e); });
  Hear<ControllerFailed>([this](const ControllerFailed& e) {
    if (failure_.empty()) failure_ = e.why;  // the first failure is kept
  });
  Hear<NodeSpawned>([this](const NodeSpawned& e) { spawned_as_[e.node] = e.spawned_as; });
  Hear<EngineWarning>([this](const EngineWarning& e) { warnings_.EngineMessage(e.t, e.kind, e.text, e.contacts); });
}

// "time,node," as every per-node event row starts.
std::string Outputs::Stamp(double t, NodeId node) const {
  std::string stamp;
  AppendFixed6(stamp, t);
  return stamp + "," + trace::CsvField(Name(node)) + ",";
}

void Outputs::Log(const LogLine& e) { log_.Row(Stamp(e.t, e.node) + trace::CsvField(e.text)); }

void Outputs::Transition(const Transitioned& e) {
  ++transitions_to_[e.to];
  transitions_.Row(Stamp(e.t, e.node) + trace::CsvField(e.from) + "," + trace::CsvField(e.to) + "," +
                   trace::CsvField(e.why));
}

void Outputs::Metric(const MetricReported& e) {
  metrics_[Name(e.node)][e.name].push_back(e.value);
  metric_rows_.Row(Stamp(e.t, e.node) + trace::CsvField(e.name) + Format(",%.9g", e.value));
}

void Outputs::Delivered(const MessageDelivered& e) {
  const Message& m = e.message;
  const double delay = m.time_received - m.time_sent;
  delays_.push_back(delay);
  std::string row;
  row.reserve(96);
  AppendFixed6(row, m.time_sent);
  row.append(",").append(Name(m.from)).append(",").append(Name(e.to)).append(",");
  row.append(DeliveryName(m.delivery)).append(",").append(std::to_string(m.payload.size())).append(",");
  AppendFixed6(row, m.time_received);
  row.append(",");
  AppendFixed6(row, delay);
  row.append(",").append(m.hops ? std::to_string(*m.hops) : "");
  messages_.Row(row);
}

void Outputs::Lost(const MessageLost& e) {
  const Message& m = e.message;
  ++messages_undelivered_;
  messages_.Row(Format("%.6f,%s,%s,%s,%zu,,,", m.time_sent, Name(m.from).c_str(), Name(e.to).c_str(),
                       DeliveryName(m.delivery), m.payload.size()));
}

void Outputs::Ended(const std::string& by, double at) {
  if (!ended_by_.empty()) return;
  ended_by_ = by;
  ended_at_ = at;
}

void Outputs::Interrupted(const std::string& by, double at) {
  if (interrupted_) return;
  interrupted_ = true;
  ended_by_ = by;
  ended_at_ = at;
}

// The smallest distance between any two robots (centre to centre), with the pair.
void Outputs::SampleMinDistance(double now, const PoseReader& world) {
  double best = HUGE_VAL;
  NodeId a = 0, b = 0;
  const auto& v = world.vehicles;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) {
      const double d = Norm(world.pose(v[i]).position() - world.pose(v[j]).position());
      if (d < best) best = d, a = v[i], b = v[j];
    }
  if (best == HUGE_VAL) return;
  min_distances_.push_back({now, best});
  min_distance_->Row(Format("%.3f,%.4f,%s,%s", now, best, Name(a).c_str(), Name(b).c_str()));
}

void Outputs::Sample(double now, bool final_row, const PoseReader& world) {
  now = std::min(now, spec_.duration);
  if (min_distance_ && !final_row) SampleMinDistance(now, world);
  last_recorded_.resize(nodes_.size());  // robots spawned while the run goes
  for (NodeId id = 0; id < nodes_.size(); ++id) {
    const Pose2D p = world.pose(id);
    auto& last = last_recorded_[id];
    // Nodes at rest add no rows (a mote appears at the start and the end unless something moves
    // it); the last row of every node is its final pose.
    if (last && (final_row ? last->time >= spec_.duration : Unmoved(p, last->pose))) continue;
    Record(now, id, p, world.velocity ? world.velocity(id) : Twist2D{},
           world.wheel_angles ? world.wheel_angles(id) : std::array<double, 3>{});
  }
}

void Outputs::Record(double now, NodeId id, const Pose2D& p, const Twist2D& velocity,
                     const std::array<double, 3>& wheel_angles) {
  last_recorded_[id] = Recorded{p, now};
  if (spec_.figures && robots::HasDrive(nodes_[id].model)) {
    trace::Track& track = tracks_[id];
    track.t.push_back(now), track.x.push_back(p.x), track.y.push_back(p.y);
  }
  trajectories_.Row(Format("%.3f,%s,%.4f,%.4f,%.4f", now, Name(id).c_str(), p.x, p.y, p.theta));
  if (bus_.Heard<PoseRow>()) bus_.Publish(PoseRow{now, id, p, velocity, wheel_angles});
}

void Outputs::FirstRow(double t, NodeId node, const Pose2D& pose) {
  last_recorded_.resize(nodes_.size());
  Record(std::min(t, spec_.duration), node, pose, Twist2D{});
}

}  // namespace sanet::sim
