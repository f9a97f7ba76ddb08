#include "ros2_agent/agent_record.h"

#include <cstdio>

#include "core/delivery.h"
#include "core/version.h"
#include "trace/earlier_run.h"
#include "trace/result_headers.h"

namespace sanet::ros2_agent {
namespace {

// Refuses another kind of results first (trace/earlier_run.h), then clears an earlier agent's.
std::string Claimed(const std::string& dir) {
  trace::ExpectEarlierKind(dir, "ros2");
  return dir;
}

}  // namespace

AgentRecord::AgentRecord(const std::string& dir, const sim::RunSpec& spec, NodeId robot, bool force)
    : spec_(spec),
      robot_(robot),
      folder_(Claimed(dir), force),
      log_(folder_.Csv("log.csv", trace::kLogHeader)),
      transitions_(folder_.Csv("transitions.csv", trace::kTransitionsHeader)),
      metrics_(folder_.Csv("metrics.csv", trace::kMetricsHeader)),
      messages_(folder_.Csv("messages.csv", trace::kMessagesHeader)),
      sent_(folder_.Csv("sent.csv", "time_sent,from,to,delivery,bytes")) {
  // First, so that a folder an agent was stopped in is known as an agent's (trace/earlier_run.h).
  nlohmann::ordered_json provenance = {
      {"scenario", spec.name}, {"robot", spec.nodes[robot].name}, {"mode", "ros2"}, {"sanet", SanetVersion()}};
  folder_.WriteWhole("provenance.json", provenance.dump(2) + "\n");
}

std::string AgentRecord::NameOf(NodeId node) const {
  return node < spec_.nodes.size() ? spec_.nodes[node].name : "all";
}

std::string AgentRecord::Stamp(double t) const { return trace::CsvTime(t) + "," + NameOf(robot_) + ","; }

void AgentRecord::Log(double t, const std::string& text) { log_.Row(Stamp(t) + trace::CsvField(text)); }

void AgentRecord::Transition(double t, const std::string& from, const std::string& to, const std::string& why) {
  transitions_.Row(Stamp(t) + trace::CsvField(from) + "," + trace::CsvField(to) + "," + trace::CsvField(why));
}

void AgentRecord::Metric(double t, const std::string& name, double value) {
  char number[64];
  std::snprintf(number, sizeof number, "%.9g", value);
  metrics_.Row(Stamp(t) + trace::CsvField(name) + "," + number);
}

void AgentRecord::Received(const Message& m) {
  messages_.Row(trace::CsvTime(m.time_sent) + "," + NameOf(m.from) + "," + NameOf(robot_) + "," +
                DeliveryName(m.delivery) + "," + std::to_string(m.payload.size()) + "," +
                trace::CsvTime(m.time_received) + "," + trace::CsvTime(m.time_received - m.time_sent) + "," +
                (m.hops ? std::to_string(*m.hops) : ""));
}

void AgentRecord::Sent(double t, NodeId to, Delivery delivery, std::size_t bytes) {
  sent_.Row(trace::CsvTime(t) + "," + NameOf(robot_) + "," + NameOf(to) + "," + DeliveryName(delivery) + "," +
            std::to_string(bytes));
}

void AgentRecord::Finish(nlohmann::ordered_json summary) {
  folder_.Commit();
  std::vector<std::string> files = folder_.files();
  files.push_back("summary.json");
  summary["files"] = files;  // what the next agent writing here clears (trace/earlier_run.h)
  folder_.WriteWhole("summary.json", summary.dump(2) + "\n");
}

}  // namespace sanet::ros2_agent
