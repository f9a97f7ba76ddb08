#include "sim/driver.h"

#include <ns3/simulator.h>

#include <algorithm>
#include <stdexcept>

#include "sim/assembly.h"

namespace sanet::sim {

// An action repeated on the simulation clock.
class Driver::Repeater {
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

Driver::Driver(Assembly& parts) : parts_(parts) {}
Driver::~Driver() = default;

void Driver::Every(double period, std::function<void()> action) {
  repeaters_.push_back(std::make_unique<Repeater>(period, std::move(action)));
}

void Driver::Stop(const std::string& why) {
  if (!stop_) stop_ = why;
  ns3::Simulator::Stop();
}

const RunSpec& Driver::spec() const { return parts_.spec(); }
RunBus& Driver::bus() { return parts_.bus(); }

double Driver::Now() const { return ns3::Simulator::Now().GetSeconds(); }
std::size_t Driver::NodeCount() const { return parts_.NodeCount(); }
std::optional<NodeId> Driver::Lookup(const std::string& name) const { return parts_.Lookup(name); }
std::string Driver::NameOf(NodeId id) const { return parts_.NameOf(id); }
const NodeSpec& Driver::Spec(NodeId id) const { return parts_.run_nodes().at(id); }
bool Driver::IsSpawned(NodeId id) const { return parts_.run_nodes().IsSpawned(id); }
std::string Driver::SpawnedAs(NodeId id) const { return parts_.run_nodes().SpawnedAs(id); }
RobotDrivers Driver::drivers() const { return parts_.drivers(); }
std::size_t Driver::SpawnedCount() const { return parts_.run_nodes().spawned(); }
Pose2D Driver::PoseOf(NodeId id) const { return parts_.TruePose(id); }

// A wrong id is a front end's bug, not a client's mistake: it throws, naming the id.
void Driver::CheckId(NodeId id) const {
  if (id >= NodeCount())
    throw std::out_of_range("no node " + std::to_string(id) + ": the run has " + std::to_string(NodeCount()));
}

std::optional<std::string> Driver::Claim(NodeId robot, const std::string& owner) {
  CheckId(robot);
  if (parts_.host(robot).has_controller())
    return "'" + NameOf(robot) + "' is driven by its scenario controller (" + Spec(robot).controller->name + ")";
  owners_.resize(NodeCount());
  const std::string& held_by = owners_.at(robot);
  if (!held_by.empty() && held_by != owner) return "robot '" + NameOf(robot) + "' is already driven by " + held_by;
  owners_[robot] = owner;
  return std::nullopt;
}

void Driver::Release(NodeId robot, const std::string& owner) {
  if (robot < owners_.size() && owners_[robot] == owner) owners_[robot].clear();
}

std::optional<std::string> Driver::OwnerOf(NodeId robot) const {
  if (robot >= owners_.size() || owners_[robot].empty()) return std::nullopt;
  return owners_[robot];
}

void Driver::CheckOwner(NodeId robot, const std::string& owner, const char* what) const {
  CheckId(robot);
  if (OwnerOf(robot) != owner)
    throw std::logic_error(owner + " " + what + " " + NameOf(robot) + ", which it does not drive (Claim it first)");
}

Node& Driver::NodeOf(NodeId robot, const std::string& owner) {
  CheckOwner(robot, owner, "drove");
  return parts_.node(robot);
}

bool Driver::SwitchedOff(NodeId robot) const {
  CheckId(robot);
  return parts_.node(robot).switched_off();
}

std::optional<BatteryReading> Driver::Battery(NodeId robot) const {
  CheckId(robot);
  return parts_.Battery(robot);
}

const SensorReadings& Driver::TakeReadings(NodeId robot, const std::string& owner) {
  CheckOwner(robot, owner, "read the sensors of");
  readings_.resize(NodeCount());
  SensorReadings& r = readings_[robot];
  if (r.time == Now()) return r;  // read already at this instant: a second read would draw noise again
  // Read as a controller reads (one path: the run's log records what the owner read).
  hosting::SimulatedNode& node = parts_.node(robot);
  r.time = Now();
  r.height = parts_.model(robot).body().position3().z;
  r.velocity = parts_.Body(robot).velocity;
  r.by_instance.clear();
  r.sampled_at.clear();
  for (const std::string& name : node.sensors().names()) {
    std::optional<SensorReading> reading = node.Sensor(name);
    if (!reading) continue;
    r.by_instance.emplace_back(name, std::move(*reading));
    if (const std::optional<double> at = node.sensors().SampledAt(name)) r.sampled_at.emplace_back(name, *at);
  }
  if (const Pose2D* truth = r.Get<Pose2D>("ground_truth")) r.ground_truth = *truth;
  return r;
}

const SensorReadings& Driver::LastReadings(NodeId robot) const {
  static const SensorReadings kNone;
  return robot < readings_.size() ? readings_[robot] : kNone;
}

std::optional<Signal> Driver::SignalBetween(NodeId from, NodeId to) const { return parts_.SignalBetween(from, to); }
void Driver::JoinTap(NodeId id, int fd, const std::string& tap_mac) {
  parts_.JoinTap(id, fd, tap_mac);
  tapped_.push_back(id);
}

bool Driver::HasTap(NodeId id) const {
  CheckId(id);
  return std::find(tapped_.begin(), tapped_.end(), id) != tapped_.end();
}

const NetworkView& Driver::NetworkOf(NodeId id) const {
  CheckId(id);
  return parts_.transport().View(id);
}
void Driver::SetRemoteInbox(RemoteInbox inbox) { parts_.SetRemoteInbox(std::move(inbox)); }
void Driver::RecordDelivery(NodeId to, const Message& message) { parts_.RecordDelivery(to, message); }
void Driver::Log(NodeId node, const std::string& text) { parts_.Log(node, text); }

NodeId Driver::Spawn(const NodeSpec& node, const std::string& spawned_as, const std::string& why) {
  return parts_.Spawn(node, spawned_as, why);
}

}  // namespace sanet::sim
