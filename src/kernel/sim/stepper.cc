#include "sim/stepper.h"

#include <ns3/core-module.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/wall_timer.h"

namespace sanet::sim {
namespace {

ns3::Time Period(double seconds) { return ns3::NanoSeconds(std::llround(seconds * 1e9)); }

double Since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Stepper::Stepper(Assembly& world, Outputs& outputs) : world_(world), outputs_(outputs), bus_(world.bus()) {
  world_.SetRunning(true);
  world_.poses().SetCatchUp([this] { CatchUp(); });
  for (NodeId id = 0; id < world_.size(); ++id) (world_.model(id).mobile() ? vehicles_ : motes_).push_back(id);
  moving_.assign(world_.size(), 0);
  for (NodeId id = 0; id < world_.size(); ++id) NoteDrive(id);
  if (bus_.Heard<StepEnded>()) world_.transport().Watch();
  if (bus_.Heard<net::FrameEvent>())
    world_.transport().ObserveFrames([&bus = bus_](const net::FrameEvent& f) { bus.Publish(f); });
  Subscribe();
}

void Stepper::Subscribe() {
  const RunSpec& spec = world_.spec();
  subscriptions_.push_back(bus_.On<LogLine>(RunStage::kControl, [this, &spec](const LogLine& e) {
    CountTowardsEnd(spec.end_when_logged, e.text, "'" + e.text + "' logged by " + world_.NameOf(e.node));
  }));
  subscriptions_.push_back(bus_.On<Transitioned>(RunStage::kControl, [this, &spec](const Transitioned& e) {
    CountTowardsEnd(spec.end_when_transition, e.to, world_.NameOf(e.node) + " entered '" + e.to + "'");
  }));
  subscriptions_.push_back(bus_.On<MetricReported>(RunStage::kControl, [this, &spec](const MetricReported& e) {
    CountTowardsEnd(spec.end_when_metric, e.name, world_.NameOf(e.node) + " reported '" + e.name + "'");
  }));
  subscriptions_.push_back(
      bus_.On<ControllerFailed>(RunStage::kControl, [this](const ControllerFailed&) { Failed(); }));
  subscriptions_.push_back(bus_.On<NodeSpawned>(RunStage::kControl, [this](const NodeSpawned& e) { Spawned(e); }));
  // A node back from the dead steps again from now on, in its round.
  subscriptions_.push_back(bus_.On<Revived>(RunStage::kControl, [this](const Revived& e) {
    if (world_.host(e.node).running()) ns3::Simulator::ScheduleNow(&Stepper::ControlStep, this, e.node);
  }));
}

void Stepper::LookAtRoutes() {
  if (!bus_.Heard<RouteChange>()) return;
  for (const RouteChange& r : routes_.Look(Now(), world_)) bus_.Publish(r);
}

Stepper::~Stepper() {
  try {
    world_.physics().Settle();  // no step may still use this stepper
  } catch (...) {               // a failed step, thrown once already (by Run, unwinding now)
  }
  world_.poses().SetCatchUp([] {});
  world_.SetRunning(false);
}

double Stepper::Now() const { return ns3::Simulator::Now().GetSeconds(); }
double Stepper::wall() const { return Since(wall_start_); }

void Stepper::Begin(std::function<void(const RunProgress&)> progress, std::function<std::string()> stop_requested) {
  progress_ = std::move(progress);
  stop_requested_ = std::move(stop_requested);
  ScheduleAll();
  world_.transport().Open(outputs_.folder());
  wall_start_ = last_progress_ = std::chrono::steady_clock::now();
  if (progress_) ns3::Simulator::ScheduleNow(&Stepper::TellProgress, this);
}

bool Stepper::Advance(double until) {
  if (ended_) return false;
  // The run ends at its duration, or once an end condition's grace is over.
  const double end = std::min(world_.spec().duration, end_at_);
  const double target = std::min(until, end);
  if (Period(target) < ns3::Simulator::Now()) return true;  // already there
  // Events at exactly `target` still run: the run covers [0, duration].
  ns3::Simulator::Stop(Period(target) - ns3::Simulator::Now() + ns3::NanoSeconds(1));
  ++advances_;
  ns3::Simulator::Run();
  world_.physics().Settle();  // a run that stopped between two physics events
  CatchUp();
  // Stopped short of the target: an end condition's grace, a failure or a stop asked for.
  ended_ = stopped_ || target >= std::min(world_.spec().duration, end_at_) || ns3::Simulator::Now() < Period(target);
  return !ended_;
}

void Stepper::StopNow(const std::string& why) {
  if (outputs_.ended_by().empty()) outputs_.Ended(why, Now());
  stopped_ = ended_ = true;
}

void Stepper::End() {
  ApplyAftermath(0);
  PublishUnsentSamples(Now());
  world_.batteries().SettleMotion();
  // Controllers finish while the run can still record what they log and measure.
  for (NodeId id = 0; id < world_.size(); ++id) world_.host(id).Finish();
  profile_.physics_wait = world_.physics().waited();
  world_.transport().Close();
  outputs_.Sample(Now(), /*final_row=*/true, Poses());
  // The run stops a nanosecond past its last events: a sample taken at its end is not taken again.
  if (world_.batteries().any() && Now() - last_energy_sample_ > 1e-6) SampleEnergy(/*again=*/false);
  bus_.Publish(RunEnded{Now()});
}

std::uint64_t Stepper::events() const {
  const std::uint64_t stops = advances_ > 0 ? advances_ - 1 : 0;
  return ns3::Simulator::GetEventCount() - stops;
}

// Order at equal times follows scheduling order: controllers start, then step, then scenario
// events, recording and physics.
void Stepper::ScheduleAll() {
  const RunSpec& spec = world_.spec();
  ns3::Simulator::ScheduleNow(&Stepper::StartControllers, this);
  for (NodeId id = 0; id < world_.size(); ++id)
    if (world_.host(id).has_controller()) ns3::Simulator::ScheduleNow(&Stepper::ControlStep, this, id);
  for (const NodeEvent& e : spec.events) ScheduleEvent(e);
  ns3::Simulator::ScheduleNow(&Stepper::Record, this);
  StartEnergySamples();
  chargers_.Start();
  // A world without vehicles has nothing to integrate: motes rest until a vehicle pushes them.
  if (!vehicles_.empty()) ns3::Simulator::ScheduleNow(&Stepper::PhysicsStep, this);
}

void Stepper::StartControllers() {
  WallTimer timer(profile_.controllers);
  for (NodeId id = 0; id < world_.size() && outputs_.failure().empty(); ++id)
    if (world_.host(id).has_controller()) world_.host(id).Start();
}

// A node's first step is its own event; from then on, controllers that share a rate step in
// one event per round, in node order, as their separate events did (same time, scheduled in
// node order).
void Stepper::ControlStep(NodeId id) {
  hosting::ControllerHost& host = world_.host(id);
  if (!host.running()) return;
  {
    WallTimer timer(profile_.controllers);
    host.Step();
  }
  if (!host.running()) return;
  const ns3::Time period = Period(host.period());
  auto [group, added] = control_rounds_.try_emplace(period.GetNanoSeconds());
  if (added) ns3::Simulator::Schedule(period, &Stepper::ControlRound, this, period.GetNanoSeconds());
  std::vector<NodeId>& round = group->second;
  // A node revived before its round noticed its death is in it still; the round stays in node order.
  const auto at = std::lower_bound(round.begin(), round.end(), id);
  if (at == round.end() || *at != id) round.insert(at, id);
}

void Stepper::ControlRound(std::int64_t period_ns) {
  std::vector<NodeId>& nodes = control_rounds_.at(period_ns);
  {
    WallTimer timer(profile_.controllers);
    for (NodeId id : nodes)
      if (world_.host(id).running()) world_.host(id).Step();
  }
  nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [this](NodeId id) { return !world_.host(id).running(); }),
              nodes.end());
  if (nodes.empty()) return void(control_rounds_.erase(period_ns));
  ns3::Simulator::Schedule(ns3::NanoSeconds(period_ns), &Stepper::ControlRound, this, period_ns);
}

// The physics event at t_k ends the step [t_k-1, t_k]: from now on the radios see its bodies
// (published when they next read a position; at once when observers watch). Then it starts the
// step [t_k, t_k+1] with the commands given so far. With a physics thread the step runs there,
// queued behind steps it has not finished, while the network goes on; anything that reads or
// drives a body waits for every step started (physics::PipelinedWorld), the radios only for the
// steps that have ended.
// Someone asked the run to stop (a signal, for the command): it ends now, its results written
// as they stand.
bool Stepper::StopIfInterrupted() {
  if (!stop_requested_ || outputs_.interrupted()) return false;
  const std::string why = stop_requested_();
  if (why.empty()) return false;
  outputs_.Interrupted(why, Now());
  stopped_ = true;
  ns3::Simulator::Stop();
  return true;
}

void Stepper::PhysicsStep() {
  if (StopIfInterrupted()) return;
  physics_steps_ = launched_;
  // Steps in which nothing else happened: with two threads, the physics has nothing to overlap there.
  const std::uint64_t events = ns3::Simulator::GetEventCount();
  if (launched_ > 0 && events == events_at_last_step_ + 1) ++quiet_physics_steps_;
  events_at_last_step_ = events;
  if (due_ != steps_.size()) {
    due_ = steps_.size();
    world_.poses().Behind();
  }
  if (bus_.Heard<StepEnded>() && launched_ > 0) {
    CatchUp();
    Notify();
  }
  ApplyAftermath(1);  // the step that ends now stays in flight
  const double dt = world_.spec().physics_step;
  // No step ends past the run: [0, duration] (events at exactly `duration` still run).
  if (Period(Now() + dt) > Period(world_.spec().duration)) return;
  StepOutcome& outcome = steps_.emplace_back();
  outcome.dt = dt;
  outcome.end = Now() + dt;
  Aftermath* aftermath = any_drive_battery_ || !samplers_.empty() ? &aftermaths_.emplace_back() : nullptr;
  outcome.number = world_.physics().StepAsync([this, &outcome, aftermath] { Integrate(outcome, aftermath); });
  if (aftermath) aftermath->number = outcome.number, aftermath->dt = dt;
  ++launched_;
  ns3::Simulator::Schedule(Period(dt), &Stepper::PhysicsStep, this);
}

// Only what moves costs anything: bodies asleep before and after the step (robots at rest
// on the 2D engine, motes) are neither sensed nor re-indexed for the radios. Runs on the physics
// thread when there is one: it steps the engine, reads vehicles_, motes_ and the models, and
// writes the bodies, their odometry, moved_, moving_, the physics and sensing times and
// `outcome`; the network's thread touches none of these without waiting for it.
void Stepper::Integrate(StepOutcome& outcome, Aftermath* aftermath) {
  CollectMoving();  // awake before the step
  {
    WallTimer timer(profile_.physics);
    world_.physics().step(outcome.dt);
  }
  CollectMoving();  // woken during it
  {
    WallTimer timer(profile_.sensing);
    for (NodeId id : moved_)
      if (world_.model(id).mobile()) world_.sensors(id).AfterPhysicsStep(outcome.end);
    for (NodeId id : samplers_) world_.sensors(id).SampleOwnClocks(outcome.end);  // moving or not
  }
  outcome.poses = world_.RadioPoses(moved_);
  if (aftermath) Leave(*aftermath);
  outcome.messages = world_.physics().TakeMessages();
  for (NodeId id : moved_) moving_[id] = 0;
  moved_.clear();
}

// On the physics thread, with Integrate: what the step leaves for its boundary. The samples are
// those its end took and those reads took before it (in order: reads happen between steps).
void Stepper::Leave(Aftermath& aftermath) {
  for (NodeId id : moved_)
    if (drives_battery_[id]) aftermath.tallies.emplace_back(id, world_.model(id).vehicle()->drive_tally());
  static thread_local std::vector<sensors::SensorSet::Sample> taken;
  for (NodeId id : samplers_) {
    taken.clear();
    world_.sensors(id).TakeSamples(taken);
    for (sensors::SensorSet::Sample& sample : taken) aftermath.samples.emplace_back(id, std::move(sample));
  }
}

// The samples due by `until` that no step took, published: at each trajectory sample of a world
// without vehicles (it has no physics steps), and at the end, with the physics settled.
void Stepper::PublishUnsentSamples(double until) {
  std::vector<sensors::SensorSet::Sample> taken;
  for (NodeId id : samplers_) {
    world_.sensors(id).SampleOwnClocks(until);
    taken.clear();
    world_.sensors(id).TakeSamples(taken);
    for (const sensors::SensorSet::Sample& sample : taken) world_.Sampled(id, sample);
  }
}

// The radios learn where the bodies were at the end of each step that has ended.
void Stepper::CatchUp() {
  world_.poses().CaughtUp();
  for (; due_ > 0; --due_) {
    world_.physics().SettleStep(steps_.front().number);
    world_.poses().Publish(steps_.front().poses);
    for (const physics::EngineMessage& m : steps_.front().messages) ReportEngineMessage(steps_.front().end, m);
    steps_.pop_front();
  }
}

// The batteries draw what the drives did, and the samples the sensors took are published, a step
// late: at each physics boundary, for the steps before the one that ends there; at the run's end,
// for all. So when a drive's work is drawn depends on the steps alone, not on who read positions,
// nor on where a script cut the run.
void Stepper::ApplyAftermath(std::size_t keep) {
  while (aftermaths_.size() > keep) {
    const Aftermath& step = aftermaths_.front();
    world_.physics().SettleStep(step.number);
    for (const auto& [id, tally] : step.tallies) world_.Drove(id, tally, step.dt);
    for (const auto& [id, sample] : step.samples) world_.Sampled(id, sample);
    aftermaths_.pop_front();
  }
}

// Its vector is read on the physics thread; it grows only between steps (a spawn settles them).
void Stepper::NoteDrive(NodeId id) {
  drives_battery_.resize(world_.size(), 0);
  const energy::NodeEnergy* energy = world_.batteries().Of(id);
  drives_battery_[id] = world_.model(id).mobile() && energy && energy->spec().drive;
  any_drive_battery_ = any_drive_battery_ || drives_battery_[id];
  if (world_.sensors(id).SamplesOnItsOwn() && std::find(samplers_.begin(), samplers_.end(), id) == samplers_.end())
    samplers_.push_back(id);
}

void Stepper::ReportEngineMessage(double t, const physics::EngineMessage& m) {
  std::vector<std::string> contacts;
  for (const physics::EngineMessage::Contact& c : m.contacts)
    contacts.push_back(world_.NameOfBody(c.a) + " and " +
                       (c.b ? world_.NameOfBody(c.b) : "world.obstacles[" + std::to_string(c.obstacle) + "]"));
  bus_.Publish(EngineWarning{t, m.kind, m.text, contacts});
}

void Stepper::CollectMoving() {
  for (const std::vector<NodeId>* group : {&vehicles_, &motes_})
    for (NodeId id : *group)
      if (!moving_[id] && world_.model(id).body().awake()) {
        moving_[id] = 1;
        moved_.push_back(id);
      }
}

void Stepper::Notify() {
  if (!bus_.Heard<StepEnded>()) return;
  const WorldSnapshot snapshot(world_, Now(), physics_steps_);
  bus_.Publish(StepEnded{snapshot});
}

void Stepper::Record() {
  if (StopIfInterrupted()) return;
  {
    WallTimer timer(profile_.recording);
    outputs_.Sample(Now(), false, Poses());
    if (vehicles_.empty()) PublishUnsentSamples(Now());
    LookAtRoutes();
  }
  if (vehicles_.empty()) Notify();  // no physics steps: observers see the world at each sample
  ns3::Simulator::Schedule(Period(world_.spec().trajectory_interval), &Stepper::Record, this);
}

PoseReader Stepper::Poses() const {
  return {[this](NodeId id) { return world_.model(id).body().pose(); },
          [this](NodeId id) { return world_.model(id).body().velocity(); },
          [this](NodeId id) { return physics::WheelAngles(world_.model(id).vehicle()); }, vehicles_};
}

void Stepper::ScheduleEvent(const NodeEvent& e) {
  const auto node = static_cast<NodeId>(e.node);
  switch (e.action) {
    case NodeEvent::Action::kSwitchOff:
      ns3::Simulator::Schedule(Period(e.time), &Stepper::SwitchOff, this, node);
      break;
    case NodeEvent::Action::kRecharge:
      ns3::Simulator::Schedule(Period(e.time), [this, node, joules = e.energy_j] { world_.Recharge(node, joules); });
      break;
  }
}

void Stepper::StartEnergySamples() {
  if (sampling_energy_ || !world_.batteries().any()) return;
  sampling_energy_ = true;
  ns3::Simulator::ScheduleNow(&Stepper::SampleEnergy, this, true);
}

void Stepper::SampleEnergy(bool again) {
  world_.batteries().SettleMotion();  // whether anyone hears the sample or not
  if (bus_.Heard<EnergySampled>()) {
    WallTimer timer(profile_.recording);
    const std::vector<EnergyLevel> levels = world_.batteries().Levels();
    bus_.Publish(EnergySampled{Now(), levels});
  }
  last_energy_sample_ = Now();
  if (again) ns3::Simulator::Schedule(Period(world_.spec().energy_interval), &Stepper::SampleEnergy, this, true);
}

void Stepper::SwitchOff(NodeId node) {
  bus_.Publish(SwitchedOff{Now(), node});
  world_.SwitchOff(node);
}

// One of the end condition's events; the run ends at the count-th (a grace period later).
void Stepper::CountTowardsEnd(const std::vector<std::string>& watched, const std::string& what,
                              const std::string& said) {
  if (std::find(watched.begin(), watched.end(), what) == watched.end() || !outputs_.ended_by().empty()) return;
  const int count = world_.spec().end_count;
  if (++end_events_ < count) return;
  outputs_.Ended(count == 1 ? said : said + " (" + std::to_string(count) + " in all)", Now());
  end_at_ = Now() + world_.spec().end_grace;  // let the last messages arrive
  ns3::Simulator::Stop(Period(world_.spec().end_grace));
}

void Stepper::Failed() {  // the outputs keep why (they heard it first)
  outputs_.Ended("controller failure", ns3::Simulator::Now().GetSeconds());
  stopped_ = true;
  ns3::Simulator::Stop();
}

// A robot joined: it moves with the others from the next physics step (one that starts now, if
// it is the world's first vehicle).
void Stepper::Spawned(const NodeSpawned& spawned) {
  const NodeId node = spawned.node;
  outputs_.FirstRow(spawned.t, node, spawned.pose);  // its first trajectory row, after the spawn itself
  moving_.resize(world_.size(), 0);
  NoteDrive(node);
  StartEnergySamples();  // the first battery may come with a spawned robot
  chargers_.Start();
  if (!world_.model(node).mobile()) return;
  if (vehicles_.empty()) ns3::Simulator::ScheduleNow(&Stepper::PhysicsStep, this);
  vehicles_.push_back(node);
}

void Stepper::TellProgress() {
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_progress_).count() >= 0.5) {
    last_progress_ = now;
    RunProgress p;
    p.time = Now(), p.duration = world_.spec().duration;
    const double wall = Since(wall_start_);
    p.real_time_factor = wall > 0 ? p.time / wall : 0;
    p.eta = p.real_time_factor > 0 ? (p.duration - p.time) / p.real_time_factor : 0;
    progress_(p);
  }
  ns3::Simulator::Schedule(ns3::Seconds(1), &Stepper::TellProgress, this);
}

}  // namespace sanet::sim
