// One run: its parts (Assembly), its clock (Stepper) and its results (Outputs), put together.
// Tests, benchmarks and the command line see this facade; front ends see its Driver only.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "hosting/controller_host.h"
#include "hosting/controller_registry.h"
#include "sim/driver.h"
#include "sim/outputs.h"
#include "sim/run_spec.h"
#include "sim/snapshot.h"
#include "sim/trace_file.h"
#include "sim/world_error.h"
#include "trace/results_folder.h"

namespace sanet::sim {

using hosting::MakeController;

struct RunOptions {
  std::string output_dir;     // "" writes nothing (tests, benchmarks)
  std::string scenario_file;  // recorded in the summary
  // About once a second of simulated time (at most twice a second of wall time): where the run is.
  std::function<void(const RunProgress&)> progress = nullptr;
  // Asked at every physics step: a reason (e.g. "interrupted by SIGINT") ends the run there, its
  // results written and marked interrupted; "" lets it go on. sim installs no signal handler.
  std::function<std::string()> stop_requested = nullptr;
  bool force = false;  // write beside files that no sanet run wrote (trace/earlier_run.h)
  // Said before the run (the scenario's warnings): listed first in summary.json's "warnings".
  std::vector<std::string> warnings = {};
  std::optional<Provenance> provenance = std::nullopt;  // written first into the folder
  // Adds fields of its own to summary.json and files of its own to the results folder (the
  // server adds its lag and the agents' reports), once the run has ended. Its "warnings" join the
  // run's (and RunResult::warnings); its other fields replace the run's (the server's "status"
  // when robots it expected never came).
  std::function<void(nlohmann::ordered_json& summary, trace::ResultsFolder& folder)> add_results = nullptr;
  // Files of the trace written above sim (trace.mcap: ros2_presentation::RunPresentation::
  // McapFile), made when the run writes a trace (sim/trace_file.h).
  std::vector<MakeTraceFile> trace_files = {};
};

// Selects ns-3's real-time scheduler for the next World: the same schedule, run against the
// wall clock (the simulation server).
void UseRealTimeClock();

class Assembly;

class World {
 public:
  // `drivers`: kFrontEnds for a world whose robots a front end drives (`sanet serve`).
  World(const RunSpec& spec, hosting::Registry& registry, RobotDrivers drivers = RobotDrivers::kScenarioControllers);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Runs for the spec's duration and writes the results (once per World). Throws WorldError
  // after writing them when a controller failed.
  RunResult Run(const RunOptions& options);
  // The same run stepped from outside (a script, a notebook): Start, then RunUntil as often as
  // wanted (simulated time `t`, events at exactly `t` included; false once the run has ended:
  // its duration, an end condition, a failure or a stop), then Finish, which writes the results
  // as Run does. Stepped in any pieces, the run gives the same results as Run.
  void Start(const RunOptions& options);
  bool RunUntil(double t);
  RunResult Finish();
  // The run was stopped (RunOptions::stop_requested) and its results say so.
  bool interrupted() const { return interrupted_; }

  const RunSpec& spec() const;
  // The parts themselves, for tests and benchmarks (sim/assembly.h); front ends use driver().
  Assembly& parts() { return *parts_; }
  // What front ends may know and do (sim/driver.h).
  Driver& driver() { return *driver_; }
  // After Run: the end condition that stopped the run ("" if it ran its duration).
  const std::string& ended_by() const { return ended_by_; }
  double ended_at() const { return ended_at_; }
  robots::NodeModel& model(NodeId id);
  std::size_t NodeCount() const;
  const RunNodes& nodes() const;  // the scenario's, then those spawned
  std::optional<NodeId> Lookup(const std::string& name) const;
  std::string NameOf(NodeId id) const;

  // Everything that happens in the run (sim/run_events.h); subscribe before Run.
  RunBus& bus() { return driver_->bus(); }
  // `observer` sees the world after every step (tests); added before Run.
  void Observe(std::function<void(const WorldSnapshot&)> observer);

  // `action` runs now (t = 0 before the run) and then every `period` s of simulated time.
  void Every(double period, std::function<void()> action) { driver_->Every(period, std::move(action)); }
  double Now() const;  // s, simulated
  // Ends the run at once (from inside it) or before its next piece; results are written as usual.
  void Stop(const std::string& why = "stopped");
  // Switches a node off now, between pieces, as a scenario's switch-off event does (recorded).
  void SwitchOff(NodeId node);

 private:
  std::unique_ptr<Assembly> parts_;
  std::unique_ptr<Driver> driver_;
  std::vector<Subscription> observers_;
  bool ran_ = false, interrupted_ = false;
  struct Running;  // between Start and Finish
  std::unique_ptr<Running> running_;
  std::string ended_by_;
  double ended_at_ = 0;
};

}  // namespace sanet::sim
