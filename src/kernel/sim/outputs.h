// The outputs of one run: every results file (trajectories, log, messages, transitions, metrics,
// smallest distance, the network's packets, routes and radio contacts), the figures, summary.json and the fingerprint.
// It hears the run's events on the bus (RunStage::kRecord) and is handed the samples and the
// network's traces; it alone decides what is written, in which form and in which order the
// fingerprint takes it. Files are written whole (trace::ResultsFolder).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/fingerprint.h"
#include "net/network_traces.h"
#include "sim/energy_outputs.h"
#include "sim/radio_contact_outputs.h"
#include "sim/run_events.h"
#include "sim/run_nodes.h"
#include "sim/run_spec.h"
#include "sim/run_warnings.h"
#include "sim/sqlite_trace.h"
#include "sim/trace_file.h"
#include "trace/figures.h"
#include "trace/results_folder.h"

namespace sanet::sim {

// Wall-clock seconds spent in each stage of the run.
struct Profile {
  double physics = 0;
  double sensing = 0;  // odometry integration after each step
  double controllers = 0;
  double recording = 0;
  double physics_wait = 0;  // wall time the network's thread waited for the physics thread
};

// Where a run is, for whoever shows its progress.
struct RunProgress {
  double time = 0, duration = 0;  // s, simulated
  double real_time_factor = 0;
  double eta = 0;  // s of wall time left at this pace
};

struct RunResult {
  double simulated = 0;  // s
  double wall = 0;       // s
  double real_time_factor = 0;
  std::uint64_t events = 0;
  std::uint64_t physics_steps = 0;
  std::uint64_t quiet_physics_steps = 0;  // in which no other event ran
  int threads = 1;
  std::string fingerprint;
  Profile profile;
  std::vector<std::string> files;  // written into the output folder
  // What the reader should know although nothing failed, found by the run (sim/run_warnings.h):
  // the command prints them; summary.json lists them after RunOptions::warnings.
  std::vector<std::string> warnings;
};

// What the outputs read of the world when they sample it.
struct PoseReader {
  std::function<Pose2D(NodeId)> pose;
  std::function<Twist2D(NodeId)> velocity;                    // world frame, for the trace
  std::function<std::array<double, 3>(NodeId)> wheel_angles;  // rad, as BodyState's
  std::vector<NodeId> vehicles;                               // the nodes that move by themselves
};

// Where a run came from: written first into its results folder (provenance.json, scenario.yaml),
// so that every folder says what made it.
struct Provenance {
  std::string effective_scenario;  // the scenario after --set and defaults, as YAML
  std::string scenario_fingerprint;
  std::vector<std::string> command;  // the command line
};

class Outputs {
 public:
  // Clears what an earlier run left in `dir` first (refusing foreign files unless `force`).
  // `nodes` grows while the run goes (robots spawned by front ends). When the scenario asks for a
  // trace and results are written, trace.sqlite and the `trace_files` are made.
  Outputs(const RunSpec& spec, const RunNodes& nodes, RunBus& bus, const std::string& dir, bool force = false,
          const std::vector<MakeTraceFile>& trace_files = {});
  void Begin(const Provenance& provenance);
  // Warnings said before the run (the command printed them): summary.json lists them first.
  void Warned(std::vector<std::string> warnings) { said_before_ = std::move(warnings); }
  trace::ResultsFolder& folder() { return folder_; }

  void Ended(const std::string& by, double at);
  // Stopped from outside at `at` (a signal): the summary says "interrupted".
  void Interrupted(const std::string& by, double at);
  bool interrupted() const { return interrupted_; }
  const std::string& failure() const { return failure_; }
  const std::string& ended_by() const { return ended_by_; }
  double ended_at() const { return ended_at_; }

  // A robot a client added at time `t`, standing at `pose`: its first trajectory row.
  void FirstRow(double t, NodeId node, const Pose2D& pose);
  // Trajectory rows (and the smallest distance) at time `now`; `final_row` for the end of the run.
  void Sample(double now, bool final_row, const PoseReader& world);

  // Writes everything whole; fills the result's fingerprint and file list. `extra` adds fields
  // to summary.json (the network's, the server's lag).
  void Finish(RunResult& result, const std::optional<net::NetworkTraces>& network, const std::string& scenario_file,
              const std::vector<Pose2D>& final_poses, nlohmann::ordered_json extra);

 private:
  void Subscribe();
  template <typename Event, typename Handler>
  void Hear(Handler handler);
  void StartTrace(const std::vector<MakeTraceFile>& trace_files);
  void Log(const LogLine& e);
  void Transition(const Transitioned& e);
  void Metric(const MetricReported& e);
  void Delivered(const MessageDelivered& e);
  // A row without time_received, delay and hops: the message reached the node but not whoever drives it.
  void Lost(const MessageLost& e);
  void SampleMinDistance(double now, const PoseReader& world);
  void Record(double now, NodeId id, const Pose2D& p, const Twist2D& velocity,
              const std::array<double, 3>& wheel_angles = {});
  void AddNetworkFiles(const net::NetworkTraces& network, Fingerprint& fp);
  void AddTapFiles(const net::NetworkTraces& network, nlohmann::ordered_json& summary);
  void WriteFigures(const std::vector<Pose2D>& final_poses, const std::optional<net::NetworkTraces>& network);
  nlohmann::ordered_json Summary(const RunResult& result, const std::string& scenario_file,
                                 const std::vector<Pose2D>& final_poses) const;
  nlohmann::ordered_json MinDistanceSummary() const;
  const std::string& Name(NodeId id) const { return nodes_.at(id).name; }
  std::string Stamp(double t, NodeId node) const;

  const RunSpec& spec_;
  const RunNodes& nodes_;
  RunBus& bus_;
  std::vector<Subscription> subscriptions_;
  RunWarnings warnings_;
  std::vector<std::string> said_before_;
  trace::ResultsFolder folder_;
  std::string scenario_fingerprint_;  // with a provenance
  trace::CsvSink &trajectories_, &log_, &messages_, &transitions_, &metric_rows_;
  trace::CsvSink* min_distance_ = nullptr;
  EnergyOutputs energy_;
  RadioContactOutputs radio_contacts_;
  std::vector<std::pair<double, double>> min_distances_;  // (time, smallest distance between robots)
  std::vector<double> delays_;                            // of every message delivered, s
  std::uint64_t messages_lost_ = 0;                       // dropped by the added message_loss
  std::uint64_t messages_undelivered_ = 0;                // reached a radio, not a controller
  std::map<std::string, std::map<std::string, std::vector<double>>> metrics_;  // node -> name -> values
  std::map<std::string, int> transitions_to_;                                  // state -> transitions into it
  struct Recorded {
    Pose2D pose;
    double time;
  };
  std::vector<std::optional<Recorded>> last_recorded_;
  std::map<NodeId, trace::Track> tracks_;     // of robots, for the figures
  std::map<NodeId, std::string> spawned_as_;  // robots that clients added, with their classes
  std::unique_ptr<SqliteTrace> sqlite_;
  std::vector<std::unique_ptr<TraceFile>> trace_files_;
  nlohmann::ordered_json trace_profile_ = nlohmann::ordered_json::object();  // the trace files' wall times
  std::string ended_by_, failure_;
  bool interrupted_ = false;
  double ended_at_ = 0;
};

}  // namespace sanet::sim
