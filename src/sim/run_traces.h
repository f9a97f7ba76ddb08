// The run's trace as one typed event stream, written twice from the same calls: trace.sqlite
// (trace::RunTrace, for sanet's viewer and SQL) and trace.mcap (RunMessages into an McapSink, ROS 2
// messages for ROS 2 tools, Foxglove and PlotJuggler), both under temporary names in the results
// folder until the results are committed. Live streams add sinks of their own: a run without a
// trace still makes the messages for them.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "net/network_traces.h"
#include "sim/mcap_sink.h"
#include "sim/run_messages.h"
#include "sim/run_nodes.h"
#include "sim/run_observer.h"
#include "sim/run_spec.h"
#include "trace/results_folder.h"
#include "trace/run_trace.h"

namespace sanet::sim {

class RunTraces {
 public:
  // Starts both files in `folder` (none: no files, only sinks added) with what does not change:
  // the run, its nodes where they start, the obstacles.
  RunTraces(const RunSpec& spec, const RunNodes& nodes, trace::ResultsFolder* folder);
  void AddSink(MessageSink& sink) { messages_.AddSink(sink); }
  bool files() const { return sqlite_ != nullptr; }
  std::size_t mcap_topics_left_out() const { return mcap_file_ ? mcap_file_->left_out() : 0; }

  void Spawned(double t, NodeId node, const std::string& spawned_as, const Pose2D& pose);
  void Pose(double t, NodeId node, const Pose2D& pose, const Twist2D& velocity);
  void Frame(const net::FrameEvent& frame);
  void Route(const RouteChange& change);
  // An application message delivered to `to`, or (`delivered` false) that reached its radio only.
  void Message(double t, const sanet::Message& m, NodeId to, bool delivered);
  void Transition(double t, NodeId node, const std::string& from, const std::string& to, const std::string& why);
  void Metric(double t, NodeId node, const std::string& name, double value);
  void Event(double t, NodeId node, const char* kind, const std::string& detail);
  // Readings as their owner took them (the SQLite trace keeps none).
  void Read(double t, NodeId node, const std::string& instance, const std::string& kind, const SensorReading& reading,
            const BodyState& body);
  void Close();
  // Wall time spent writing each file so far (for trace.mcap: making the messages too), s.
  double sqlite_seconds() const { return sqlite_seconds_; }
  double mcap_seconds() const { return mcap_seconds_; }

 private:
  void Describe(const RunSpec& spec);
  const RunNodes& nodes_;
  std::unique_ptr<trace::RunTrace> sqlite_;
  std::unique_ptr<McapSink> mcap_file_;
  RunMessages messages_;
  double sqlite_seconds_ = 0, mcap_seconds_ = 0;
};

}  // namespace sanet::sim
