#include "sim/world.h"

#include <ns3/global-value.h>
#include <ns3/simulator.h>
#include <ns3/string.h>

#include <nlohmann/json.hpp>

#include "sim/stepper.h"

namespace sanet::sim {
namespace {

class FunctionObserver : public StepObserver {
 public:
  explicit FunctionObserver(std::function<void(const WorldSnapshot&)> f) : f_(std::move(f)) {}
  void AfterStep(const WorldSnapshot& snapshot) override { f_(snapshot); }

 private:
  std::function<void(const WorldSnapshot&)> f_;
};

}  // namespace

void UseRealTimeClock() {
  ns3::GlobalValue::Bind("SimulatorImplementationType", ns3::StringValue("ns3::RealtimeSimulatorImpl"));
}

void World::Observe(std::function<void(const WorldSnapshot&)> observer) {
  owned_observers_.push_back(std::make_unique<FunctionObserver>(std::move(observer)));
  AddObserver(*owned_observers_.back());
}

// An action repeated on the simulation clock.
class World::Repeater {
 public:
  Repeater(double period, std::function<void()> action) : period_(period), action_(std::move(action)) {
    ns3::Simulator::ScheduleNow(&Repeater::Tick, this);
  }

 private:
  void Tick() {
    action_();
    ns3::Simulator::Schedule(ns3::Seconds(period_), &Repeater::Tick, this);
  }
  double period_;
  std::function<void()> action_;
};

World::World(const RunSpec& spec, agents::Registry& registry) : parts_(spec, registry) {}
World::~World() = default;

void World::Every(double period, std::function<void()> action) {
  repeaters_.push_back(std::make_unique<Repeater>(period, std::move(action)));
}

double World::Now() const { return ns3::Simulator::Now().GetSeconds(); }
void World::Stop() { ns3::Simulator::Stop(); }

RunResult World::Run(const RunOptions& options) {
  if (ran_) throw WorldError("a World runs once");
  ran_ = true;
  Outputs outputs(spec(), options.output_dir, options.force);
  if (options.provenance) outputs.Begin(*options.provenance);
  Stepper stepper(parts_, outputs, observers_);
  stepper.Run(options.progress);

  RunResult result;
  result.simulated = std::min(stepper.Now(), spec().duration);
  result.wall = stepper.wall();
  result.real_time_factor = result.wall > 0 ? result.simulated / result.wall : 0;
  result.events = ns3::Simulator::GetEventCount();
  result.physics_steps = stepper.physics_steps();
  result.quiet_physics_steps = stepper.quiet_physics_steps();
  result.threads = spec().threads;
  result.profile = stepper.profile();
  ended_by_ = outputs.ended_by();
  interrupted_ = outputs.interrupted();
  ended_at_ = outputs.ended_at();
  std::vector<Pose2D> final_poses;
  for (NodeId id = 0; id < parts_.size(); ++id) final_poses.push_back(parts_.model(id).body().pose());
  nlohmann::ordered_json extra = nlohmann::ordered_json::object();
  if (options.add_results) options.add_results(extra, outputs.folder());
  outputs.Finish(result, parts_.transport().Traces(), options.scenario_file, final_poses, extra);
  if (!outputs.failure().empty()) throw WorldError(outputs.failure());
  return result;
}

}  // namespace sanet::sim
