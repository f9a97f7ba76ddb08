#include "sim/world.h"

#include <ns3/global-value.h>
#include <ns3/simulator.h>
#include <ns3/string.h>

#include <nlohmann/json.hpp>

#include "sim/assembly.h"
#include "sim/stepper.h"

namespace sanet::sim {

void UseRealTimeClock() {
  ns3::GlobalValue::Bind("SimulatorImplementationType", ns3::StringValue("ns3::RealtimeSimulatorImpl"));
}

void World::Observe(std::function<void(const WorldSnapshot&)> observer) {
  observers_.push_back(bus().On<StepEnded>(RunStage::kObserve, [observer](const StepEnded& e) { observer(e.world); }));
}

World::World(const RunSpec& spec, hosting::Registry& registry, RobotDrivers drivers)
    : parts_(std::make_unique<Assembly>(spec, registry, drivers)), driver_(std::make_unique<Driver>(*parts_)) {}
World::~World() = default;

const RunSpec& World::spec() const { return parts_->spec(); }
robots::NodeModel& World::model(NodeId id) { return parts_->model(id); }
std::size_t World::NodeCount() const { return parts_->NodeCount(); }
const RunNodes& World::nodes() const { return parts_->run_nodes(); }
std::optional<NodeId> World::Lookup(const std::string& name) const { return parts_->Lookup(name); }
std::string World::NameOf(NodeId id) const { return parts_->NameOf(id); }
double World::Now() const { return ns3::Simulator::Now().GetSeconds(); }
void World::Stop(const std::string& why) { driver_->Stop(why); }

struct World::Running {
  Running(World& world, const RunOptions& run_options)
      : options(run_options),
        outputs(world.spec(), world.parts_->run_nodes(), world.parts_->bus(), options.output_dir, options.force,
                options.trace_files),
        stepper(*world.parts_, outputs) {}
  RunOptions options;
  Outputs outputs;
  Stepper stepper;
};

void World::SwitchOff(NodeId node) {
  if (!running_) throw WorldError("a node is switched off while the run goes: between Start and Finish");
  running_->stepper.SwitchOff(node);
}

RunResult World::Run(const RunOptions& options) {
  Start(options);
  RunUntil(spec().duration);
  return Finish();
}

void World::Start(const RunOptions& options) {
  if (ran_) throw WorldError("a World runs once");
  ran_ = true;
  running_ = std::make_unique<Running>(*this, options);
  if (options.provenance) running_->outputs.Begin(*options.provenance);
  running_->outputs.Warned(options.warnings);
  running_->stepper.Begin(options.progress, options.stop_requested);
}

bool World::RunUntil(double t) {
  if (!running_) throw WorldError("RunUntil before Start, or after Finish");
  Stepper& stepper = running_->stepper;
  if (const auto& why = driver_->stop_requested()) return stepper.StopNow(*why), false;
  const bool goes_on = stepper.Advance(t);
  if (const auto& why = driver_->stop_requested()) return stepper.StopNow(*why), false;
  return goes_on;
}

RunResult World::Finish() {
  if (!running_) throw WorldError("Finish before Start, or twice");
  const std::unique_ptr<Running> run = std::move(running_);
  Stepper& stepper = run->stepper;
  Outputs& outputs = run->outputs;
  if (!stepper.ended()) stepper.StopNow("finished early by whoever stepped it (World::Finish)");
  stepper.End();
  driver().RunEnded();
  RunResult result;
  result.simulated = std::min(stepper.Now(), spec().duration);
  result.wall = stepper.wall();
  result.real_time_factor = result.wall > 0 ? result.simulated / result.wall : 0;
  result.events = stepper.events();
  result.physics_steps = stepper.physics_steps();
  result.quiet_physics_steps = stepper.quiet_physics_steps();
  result.threads = spec().threads;
  result.profile = stepper.profile();
  ended_by_ = outputs.ended_by();
  interrupted_ = outputs.interrupted();
  ended_at_ = outputs.ended_at();
  std::vector<Pose2D> final_poses;
  for (NodeId id = 0; id < parts_->size(); ++id) final_poses.push_back(parts_->model(id).body().pose());
  nlohmann::ordered_json extra = nlohmann::ordered_json::object();
  if (parts_->batteries().any()) extra["energy"] = parts_->batteries().Summary(parts_->run_nodes());
  if (run->options.add_results) run->options.add_results(extra, outputs.folder());
  outputs.Finish(result, parts_->transport().Traces(), run->options.scenario_file, final_poses, extra);
  if (!outputs.failure().empty()) throw WorldError(outputs.failure());
  return result;
}

}  // namespace sanet::sim
