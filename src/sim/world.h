// One run: the physics world, the nodes with their models and controllers, the ns-3 nodes whose
// mobility reads physics, and the events that advance them all on ns-3's clock.
//
// ns-3's simulator is process-wide, so only one World may exist at a time (checked).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "agents/controller_registry.h"
#include "agents/simulated_node.h"
#include "core/random_stream.h"
#include "net/transport.h"
#include "sim/run_spec.h"
#include "trace/csv_sink.h"

namespace sanet::sim {

class WorldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Builds the controller of a node spec: loads its library if any, creates it from its
// parameters and rejects unknown parameters. Throws ParamError or agents::RegistryError.
std::unique_ptr<Controller> MakeController(const ControllerSpec& spec, agents::Registry& registry);

struct RunOptions {
  std::string output_dir;     // "" writes nothing (tests, benchmarks)
  std::string scenario_file;  // recorded in the summary
  bool progress = false;      // print simulated time, real-time factor and ETA to stderr
  // Adds fields of its own to summary.json (the server adds its lag).
  std::function<void(nlohmann::ordered_json&)> add_to_summary;
};

// Wall-clock seconds spent in each stage of the run.
struct Profile {
  double physics = 0;
  double sensing = 0;  // odometry integration after each step
  double controllers = 0;
  double recording = 0;
};

struct RunResult {
  double simulated = 0;  // s
  double wall = 0;       // s
  double real_time_factor = 0;
  std::uint64_t events = 0;
  std::uint64_t physics_steps = 0;
  std::string fingerprint;
  Profile profile;
  std::vector<std::string> files;  // written into the output folder
};

class World : public agents::NodeDirectory {
 public:
  World(const RunSpec& spec, agents::Registry& registry);
  ~World() override;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Runs for the spec's duration and writes the results (once per World).
  RunResult Run(const RunOptions& options);

  const RunSpec& spec() const { return spec_; }
  // After Run: the end condition that stopped the run ("" if it ran its duration).
  const std::string& ended_by() const { return ended_by_; }
  double ended_at() const { return ended_at_; }  // s, when the end condition was met
  robots::NodeModel& model(NodeId id) { return *models_.at(id); }
  // Called after every physics step with the simulated time (tests watch the world with it).
  void SetStepObserver(std::function<void(double)> observer) { step_observer_ = std::move(observer); }

  // NodeDirectory
  std::optional<NodeId> Lookup(const std::string& name) const override;
  std::string NameOf(NodeId id) const override { return id < spec_.nodes.size() ? spec_.nodes[id].name : ""; }
  std::size_t NodeCount() const override { return spec_.nodes.size(); }
  Pose2D TruePose(NodeId node) const override;
  void Log(NodeId node, const std::string& text) override;

 private:
  struct Outputs;
  void PhysicsStep();
  void ControlStep(std::size_t index);
  void Record(bool final_row);
  void RecordMinDistance(double now);
  void Receive(NodeId to, const Message& message);
  void Deliver(NodeId to, const Message& message);
  void ShowProgress();
  void SwitchOff(NodeId node);
  void WriteFigures(const std::string& dir, RunResult& result);
  void WriteSummary(const RunOptions& options, RunResult& result, const nlohmann::ordered_json& extra);

  RunSpec spec_;
  RandomStream impairments_;
  std::unique_ptr<physics::PhysicsWorld> physics_;
  std::vector<std::unique_ptr<robots::NodeModel>> models_;
  std::vector<robots::NodeModel*> vehicles_;  // the models that move by themselves
  std::vector<std::string> vehicle_names_;
  std::unique_ptr<net::Transport> transport_;
  std::vector<std::unique_ptr<agents::SimulatedNode>> nodes_;
  std::vector<std::unique_ptr<Controller>> controllers_;  // null where a node has none
  struct Recorded {
    Pose2D pose;
    double time;
  };
  std::vector<std::optional<Recorded>> last_recorded_;
  std::unique_ptr<Outputs> out_;
  std::function<void(double)> step_observer_;
  Profile profile_;
  std::uint64_t physics_steps_ = 0;
  bool ran_ = false;
  std::string ended_by_;
  double ended_at_ = 0;
  std::vector<bool> switched_off_;
  std::chrono::steady_clock::time_point wall_start_, last_progress_;
};

}  // namespace sanet::sim
