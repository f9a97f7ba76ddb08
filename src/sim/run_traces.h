// The run's trace as one typed event stream, written twice from the same calls: trace.sqlite
// (trace::RunTrace, for sanet's viewer and SQL) and trace.mcap (McapLog, ROS 2 messages for ROS 2
// tools, Foxglove and PlotJuggler). Both take their temporary names in the results folder and
// their own names when the results are committed.
#pragma once

#include <optional>
#include <string>

#include "net/network_traces.h"
#include "sim/mcap_log.h"
#include "sim/run_nodes.h"
#include "sim/run_observer.h"
#include "sim/run_spec.h"
#include "trace/results_folder.h"
#include "trace/run_trace.h"

namespace sanet::sim {

class RunTraces {
 public:
  using Scanner = McapLog::Scanner;
  // Starts both with what does not change: the run, its nodes where they start, the obstacles.
  RunTraces(const RunSpec& spec, const RunNodes& nodes, trace::ResultsFolder& folder);

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
  void Odometry(double t, NodeId node, const Pose2D& odometry, const BodyState& body);
  void Scan(double t, NodeId node, Scanner which, const RangeScan& scan);
  void Close();
  // Wall time spent writing each file so far, s.
  double sqlite_seconds() const { return sqlite_seconds_; }
  double mcap_seconds() const { return mcap_seconds_; }

 private:
  void Describe(const RunSpec& spec);
  const RunNodes& nodes_;
  trace::RunTrace sqlite_;
  McapLog mcap_;
  double sqlite_seconds_ = 0, mcap_seconds_ = 0;
};

}  // namespace sanet::sim
