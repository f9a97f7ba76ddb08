// The one clock of a run: every stage is an event on ns-3's scheduler. At t = 0 the
// controllers start, then (at their own rates) control steps; every physics event ends the step
// in flight (the radios and observers see its bodies) and starts the next, which integrates the
// bodies (stage "physics") and the odometry (stage "sensing"), on a thread of its own in a run
// with two;
// every trajectory interval the outputs sample it (stage "recording"); scenario events switch
// nodes off. The stepper also applies the end conditions and ends the run on a controller's
// failure, keeping what was recorded.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "sim/assembly.h"
#include "sim/chargers.h"
#include "sim/outputs.h"
#include "sim/route_watch.h"
#include "sim/run_events.h"
#include "sim/snapshot.h"

namespace sanet::sim {

// It hears the run's events last (RunStage::kControl): the end conditions count log lines,
// transitions and metrics; a controller's failure stops the run; a spawned robot joins the steps.
// It publishes what the clock finds: the world after each step, frames, route changes, the
// engine's messages, switch-offs.
class Stepper {
 public:
  Stepper(Assembly& world, Outputs& outputs);
  ~Stepper();

  // A run in three parts: Begin schedules it (`progress`, if given, hears where the run is;
  // RunOptions), Advance runs it to simulated time `until` (events at exactly `until` included)
  // and says whether it goes on (false once the duration is reached, or an end condition, a
  // failure or a stop ended it), End closes it. Advancing in many pieces gives the same run as
  // in one.
  void Begin(std::function<void(const RunProgress&)> progress, std::function<std::string()> stop_requested);
  bool Advance(double until);
  void End();
  bool ended() const { return ended_; }
  // Ends the run here, before its duration: the outputs say `why` (unless something ended it first).
  void StopNow(const std::string& why);
  // Events the run's own (the scheduler also counts the stops that end each Advance but the last).
  std::uint64_t events() const;
  const Profile& profile() const { return profile_; }
  std::uint64_t physics_steps() const { return physics_steps_; }
  // Physics steps in which no other event ran (no network, controller or recording event).
  std::uint64_t quiet_physics_steps() const { return quiet_physics_steps_; }
  double wall() const;  // s since Run began
  double Now() const;   // s, simulated

  // The node stops for good (a scenario's switch-off event, or a script's), recorded as an event.
  void SwitchOff(NodeId node);

 private:
  void Subscribe();
  void Failed();  // a controller failed: the run ends now
  void Spawned(const NodeSpawned& spawned);
  void ScheduleAll();
  void StartControllers();
  void ControlStep(NodeId node);
  void ControlRound(std::int64_t period_ns);
  void PhysicsStep();
  struct StepOutcome {
    double dt = 0;                                 // s
    std::uint64_t number = 0;                      // the physics world's
    std::vector<RadioPose> poses;                  // of the bodies that moved, at its end
    double end = 0;                                // s, simulated
    std::vector<physics::EngineMessage> messages;  // the engine's, during it
  };
  // What a step leaves for the next step's boundary (ApplyAftermath), whoever reads positions in
  // between: what the drives of robots with batteries did, drawn from their batteries, and the
  // samples sensors took on their own clocks during it, published.
  struct Aftermath {
    std::uint64_t number = 0;  // the physics world's
    double dt = 0;
    std::vector<std::pair<NodeId, physics::DriveTally>> tallies;  // the robots that moved
    std::vector<std::pair<NodeId, sensors::SensorSet::Sample>> samples;
  };
  void Integrate(StepOutcome& outcome, Aftermath* aftermath);
  void Leave(Aftermath& aftermath);
  void PublishUnsentSamples(double until);  // those no physics step took
  void CatchUp();
  void ApplyAftermath(std::size_t keep);  // all steps' but the last `keep`
  void NoteDrive(NodeId id);              // whether its drive draws on a battery, its sensors sample
  void Record();
  void StartEnergySamples();      // once some node has a battery
  void SampleEnergy(bool again);  // every battery, for energy.csv; `again`: and the next sample
  void ScheduleEvent(const NodeEvent& event);
  void Notify();
  void ReportEngineMessage(double t, const physics::EngineMessage& message);
  void LookAtRoutes();
  void CollectMoving();
  void TellProgress();
  bool StopIfInterrupted();
  void CountTowardsEnd(const std::vector<std::string>& watched, const std::string& what, const std::string& said);
  PoseReader Poses() const;

  Assembly& world_;
  Outputs& outputs_;
  RunBus& bus_;
  std::vector<Subscription> subscriptions_;
  std::vector<NodeId> vehicles_, motes_;
  std::map<std::int64_t, std::vector<NodeId>> control_rounds_;  // period (ns) -> nodes, in node order
  std::deque<Aftermath> aftermaths_;                            // of steps started, not applied yet
  std::deque<StepOutcome> steps_;                               // started, and not yet published to the radios
  std::size_t due_ = 0;                                         // the first due_ of them have ended
  std::uint64_t launched_ = 0;
  std::vector<NodeId> moved_;  // bodies awake before or after the step in flight (physics thread)
  std::vector<char> moving_;   // per node: listed in moved_
  Chargers chargers_{world_};
  std::vector<char> drives_battery_;  // per node: a robot with a battery
  bool any_drive_battery_ = false;
  std::vector<NodeId> samplers_;  // nodes with a sensor that samples on its own clock (read on the physics thread)
  RouteWatch routes_;
  double last_energy_sample_ = -1;  // s
  bool sampling_energy_ = false;
  Profile profile_;
  std::uint64_t physics_steps_ = 0;
  std::uint64_t quiet_physics_steps_ = 0, events_at_last_step_ = 0;
  int end_events_ = 0;  // of the end condition, so far
  std::chrono::steady_clock::time_point wall_start_, last_progress_;
  std::function<void(const RunProgress&)> progress_;
  std::function<std::string()> stop_requested_;
  std::uint64_t advances_ = 0;
  bool ended_ = false;                                       // Advance has nothing more to run
  bool stopped_ = false;                                     // a failure or a stop asked for ended it at once
  double end_at_ = std::numeric_limits<double>::infinity();  // s: an end condition's grace is over
};

}  // namespace sanet::sim
