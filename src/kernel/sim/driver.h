// The one seam between a running world and its front ends (the USARSim robot server, the WSS
// endpoint, launch's radio taps, and those to come): what they may know and do, and nothing of
// the assembly behind it. A robot has at most one owner at a time, the front end that drives it;
// another front end asking for it is refused with a sentence naming the owner. The owner reads a
// robot's sensors (one read per sensor period: noisy sensors draw from the node's random stream,
// so a second read would change the run); everyone else sees the readings it last took.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sanet/node.h"
#include "sim/remote_inbox.h"
#include "sim/run_events.h"
#include "sim/run_spec.h"
#include "sim/snapshot.h"

namespace sanet::sim {

class Assembly;

// A robot's sensors, read once by its owner: every instance, as Node::Sensor gives it.
struct SensorReadings {
  double time = -1;     // s, simulated; -1 before the first read
  Pose2D ground_truth;  // the ground_truth sensor's reading
  double height = 0;    // m, of the body's centre
  Twist2D velocity;     // world frame
  // Every instance that gave a reading, in the order of sensors::PresentationOrder.
  std::vector<std::pair<std::string, SensorReading>> by_instance;
  // When each instance that samples on its own clock took the reading it gave (s, simulated).
  std::vector<std::pair<std::string, double>> sampled_at;

  // Instance `name`'s reading if it is a T; null otherwise.
  template <typename T>
  const T* Get(const std::string& name) const {
    for (const auto& [instance, reading] : by_instance)
      if (instance == name) return std::get_if<T>(&reading);
    return nullptr;
  }
  // The default instances of the first kinds.
  std::optional<Pose2D> odometry() const {
    const Pose2D* pose = Get<Pose2D>("odometry");
    return pose ? std::optional<Pose2D>(*pose) : std::nullopt;
  }
  const RangeScan* laser() const { return Get<RangeScan>("laser"); }
  // When instance `name`'s reading was taken, if it samples on its own clock (else at the read).
  std::optional<double> SampledAt(const std::string& name) const {
    for (const auto& [instance, at] : sampled_at)
      if (instance == name) return at;
    return std::nullopt;
  }
  const RangeScan* ir() const { return Get<RangeScan>("ir"); }
};

class Driver {
 public:
  explicit Driver(Assembly& parts);
  ~Driver();
  Driver(const Driver&) = delete;
  Driver& operator=(const Driver&) = delete;

  // The run as loaded, which never changes (spawned robots are in Spec(id), not here).
  const RunSpec& spec() const;
  double Now() const;  // s, simulated
  std::size_t NodeCount() const;
  std::optional<NodeId> Lookup(const std::string& name) const;
  std::string NameOf(NodeId id) const;
  const NodeSpec& Spec(NodeId id) const;  // the scenario's node, or the spawned robot's
  bool IsSpawned(NodeId id) const;
  std::string SpawnedAs(NodeId id) const;  // the class a client spawned it as; "" otherwise
  std::size_t SpawnedCount() const;
  // Whether the robots' scenario controllers run here or front ends drive them (World's choice).
  RobotDrivers drivers() const;
  // Where the body stands now (the truth, not a sensor read: it draws no noise).
  Pose2D PoseOf(NodeId id) const;

  // Ownership. Claim returns nothing when granted (or already held by `owner`), or the refusal:
  // another front end drives it, or its scenario controller runs here (a world built with
  // RobotDrivers::kScenarioControllers, or a mote's controller). Every call that takes a node id
  // throws std::out_of_range for an id the run does not have.
  std::optional<std::string> Claim(NodeId robot, const std::string& owner);
  void Release(NodeId robot, const std::string& owner);
  std::optional<std::string> OwnerOf(NodeId robot) const;

  // The node its owner drives through, as a controller would: every Node check applies. Throws
  // std::logic_error for anyone but the owner.
  Node& NodeOf(NodeId robot, const std::string& owner);
  bool SwitchedOff(NodeId robot) const;
  // The robot's battery now (docs/energy.md); empty for an infinite supply. It draws no noise.
  std::optional<BatteryReading> Battery(NodeId robot) const;
  // The owner's read of every sensor; throws std::logic_error for anyone else. A second read at
  // the same simulated time gives the first (noisy sensors draw once).
  const SensorReadings& TakeReadings(NodeId robot, const std::string& owner);
  // What the owner read last (time -1 if it never read), for everyone else.
  const SensorReadings& LastReadings(NodeId robot) const;

  // The radio between two nodes now; empty without ns-3's network.
  std::optional<Signal> SignalBetween(NodeId from, NodeId to) const;
  // Joins a real IP stack (a network namespace's tap `fd`, MAC `tap_mac`) to node `id`'s radio.
  void JoinTap(NodeId id, int fd, const std::string& tap_mac);
  // Whether a real IP stack is joined to the node's radio: its programs' traffic crosses it.
  bool HasTap(NodeId id) const;
  // What the node's network layer knows now (routing table, neighbours), for anyone to read;
  // changing it (invalidate, request) is its owner's, through NodeOf.
  const NetworkView& NetworkOf(NodeId id) const;
  // Messages that reach a node driven from outside go to `inbox` (nullptr: none).
  void SetRemoteInbox(RemoteInbox inbox);
  // A message that reached `to` outside the run's own transport, recorded as delivered.
  void RecordDelivery(NodeId to, const Message& message);
  // A line in the node's log (log.csv), from the front end.
  void Log(NodeId node, const std::string& text);

  // Adds a robot to the running world, as the class `spawned_as` that its front end names (the
  // front end decided it may: where it stands, its name); `why` goes to its log. Returns its id.
  NodeId Spawn(const NodeSpec& node, const std::string& spawned_as, const std::string& why);

  // On the run's clock: `action` now (t = 0 before the run starts) and then every `period` s of
  // simulated time (a front end's socket polling).
  void Every(double period, std::function<void()> action);
  // Everything that happens in the run (sim/run_events.h). Subscribe before the run starts: the
  // run decides then whether to trace frames and snapshots at all.
  RunBus& bus();
  // Ends the run at once (from inside it) or before its next piece (between World::RunUntil
  // calls); results are written as usual and summary.json's ended_by says `why`.
  void Stop(const std::string& why = "stopped by a front end");
  // When the run has ended (the run's own controllers have finished, Controller::Finish) and
  // before its results are written: `action`, so that a front end lets the controllers it serves
  // finish too and records what they log. Added before the run starts; World calls RunEnded.
  void AtEnd(std::function<void()> action) { at_end_.push_back(std::move(action)); }
  void RunEnded() {
    for (const auto& action : at_end_) action();
  }
  const std::optional<std::string>& stop_requested() const { return stop_; }

 private:
  class Repeater;
  void CheckId(NodeId id) const;
  void CheckOwner(NodeId robot, const std::string& owner, const char* what) const;
  Assembly& parts_;
  std::vector<std::unique_ptr<Repeater>> repeaters_;
  std::vector<std::string> owners_;  // per node; "" for none
  std::vector<SensorReadings> readings_;
  std::vector<NodeId> tapped_;
  std::optional<std::string> stop_;
  std::vector<std::function<void()>> at_end_;
};

}  // namespace sanet::sim
