// What an agent on a ROS 2 robot records, with no server to record it: its own results folder
// with log.csv, transitions.csv, metrics.csv and messages.csv in the formats of a run's
// (docs/scenario.md; messages.csv: what reached this robot), sent.csv (what it sent:
// time_sent,from,to,delivery,bytes) and summary.json, every time on the agent's clock. Files are
// written whole when the agent ends (temporary names until then), also when it is stopped.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "sanet/message.h"
#include "sim/run_spec.h"
#include "trace/results_folder.h"

namespace sanet::ros2_agent {

class AgentRecord {
 public:
  // Clears what an earlier agent left in `dir` (refusing a folder of other files unless `force`).
  AgentRecord(const std::string& dir, const sim::RunSpec& spec, NodeId robot, bool force);

  void Log(double t, const std::string& text);
  void Transition(double t, const std::string& from, const std::string& to, const std::string& why);
  void Metric(double t, const std::string& name, double value);
  void Received(const Message& m);
  void Sent(double t, NodeId to, Delivery delivery, std::size_t bytes);
  // Moves every file into place, then writes summary.json (with the list of files).
  void Finish(nlohmann::ordered_json summary);
  const std::string& dir() const { return folder_.dir(); }

 private:
  std::string Stamp(double t) const;
  std::string NameOf(NodeId node) const;
  const sim::RunSpec& spec_;
  NodeId robot_;
  trace::ResultsFolder folder_;
  trace::CsvSink &log_, &transitions_, &metrics_, &messages_, &sent_;
};

}  // namespace sanet::ros2_agent
