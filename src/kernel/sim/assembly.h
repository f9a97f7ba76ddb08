// A run's parts, built from its spec: the physics world and its bodies, one ns-3 node per
// scenario node whose mobility holds its body's pose at the last step boundary, the transport (ns-3's network or the
// local stand-in), and for every node the simulated node its drivers see and the host of its controller. Nothing here
// advances time: that is the stepper's job.
//
// ns-3's simulator is process-wide, so only one Assembly may exist at a time (checked).
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include "hosting/controller_host.h"
#include "hosting/simulated_node.h"
#include "physics/pipelined_world.h"
#include "sim/message_ledger.h"
#include "sim/node_batteries.h"
#include "sim/pose_pipeline.h"
#include "sim/radio_calibration.h"
#include "sim/remote_inbox.h"
#include "sim/run_events.h"
#include "sim/run_nodes.h"
#include "sim/run_spec.h"
#include "sim/snapshot.h"
#include "sim/world_error.h"

namespace sanet::net {
class BodyMobilityModel;
class LocalTransport;
class WirelessNetwork;
}  // namespace sanet::net

namespace sanet::sim {

class Assembly : public hosting::NodeDirectory, public SnapshotSource {
 public:
  Assembly(const RunSpec& spec, hosting::Registry& registry, RobotDrivers drivers);
  ~Assembly() override;
  Assembly(const Assembly&) = delete;
  Assembly& operator=(const Assembly&) = delete;

  // The run as loaded, and its nodes now (the scenario's, then those spawned).
  const RunSpec& spec() const { return spec_; }
  const RunNodes& run_nodes() const { return run_nodes_; }
  std::size_t size() const { return nodes_.size(); }
  hosting::SimulatedNode& node(NodeId id) { return *nodes_.at(id); }
  hosting::ControllerHost& host(NodeId id) { return *hosts_.at(id); }
  robots::NodeModel& model(NodeId id) { return *models_.at(id); }
  sensors::SensorSet& sensors(NodeId id) { return *sensors_.at(id); }
  // The bodies' world; with `world.threads: 2` its steps run on a thread of their own.
  physics::PipelinedWorld& physics() { return *physics_; }
  MessageLedger& transport() { return *transport_; }
  // True for a robot that a front end drives instead of its scenario controller.
  bool remote(NodeId id) const;
  RobotDrivers drivers() const { return drivers_; }

  // The radios read positions published at step boundaries, never the bodies themselves
  // (sim/pose_pipeline.h).
  PosePipeline& poses() { return *poses_; }
  // The poses of `moved` bodies now, for PosePipeline::Publish (on the physics thread, after its step).
  std::vector<RadioPose> RadioPoses(const std::vector<NodeId>& moved) const;
  // The node whose body `body` is ("a body" if none is).
  std::string NameOfBody(const physics::Body* body) const;

  // Where everything that happens in the run is published (sim/run_events.h): what the nodes
  // report only while the run goes (SetRunning, by the stepper), as only then is it recorded.
  RunBus& bus() { return bus_; }
  void SetRunning(bool running) { running_ = running; }
  void SetRemoteInbox(RemoteInbox inbox) { remote_inbox_ = std::move(inbox); }
  void SwitchOff(NodeId id);
  // Energy into node `id`'s battery (`joules`, or to full); a dead node recharged above its
  // revive level comes back. Refused (a log line) for a node without energy.
  void Recharge(NodeId id, std::optional<double> joules);
  // What robot `id`'s drive did up to the end of a step of `dt` seconds: its battery draws it.
  void Drove(NodeId id, const physics::DriveTally& tally, double dt);
  const NodeBatteries& batteries() const { return batteries_; }
  bool SwitchedOff(NodeId id) const { return off_for_good_.at(id); }  // by an event, for good
  // Adds a robot to the running world (its front end checked where it stands): its body, its own ns-3 node
  // with the scenario's radio and routing, a simulated node and a host without a controller.
  // Every other node can see it from now on. Returns its id, the next one.
  NodeId Spawn(const NodeSpec& node, const std::string& spawned_as, const std::string& why);
  std::size_t spawned() const { return run_nodes_.spawned(); }
  // Joins a real IP stack (an agent's network namespace) to node `id`'s radio through the tap
  // `fd`, whose interface has the MAC address `tap_mac` ("02:..."). Needs ns-3's network.
  void JoinTap(NodeId id, int fd, const std::string& tap_mac);
  // How strongly `to` hears `from` now: from ns-3's channel at the bodies' positions. Empty
  // without ns-3's network.
  std::optional<Signal> SignalBetween(NodeId from, NodeId to) const;
  // A message that reached a node outside the run's own transport (between agents, over UDP),
  // recorded as delivered.
  void RecordDelivery(NodeId to, const Message& message) { Tell(MessageDelivered{to, message}); }

  // NodeDirectory
  std::optional<NodeId> Lookup(const std::string& name) const override;
  std::string NameOf(NodeId id) const override { return run_nodes_.NameOf(id); }
  std::size_t NodeCount() const override { return run_nodes_.size(); }
  Pose2D TruePose(NodeId node) const override { return models_.at(node)->body().pose(); }
  void Log(NodeId node, const std::string& text) override;
  void Transition(NodeId node, const std::string& from, const std::string& to, const std::string& why) override;
  void Metric(NodeId node, const std::string& name, double value) override;
  void ReadSensor(NodeId node, const std::string& instance, const std::string& kind,
                  const SensorReading& reading) override;
  std::optional<BatteryReading> Battery(NodeId node) const override;

  // SnapshotSource
  BodyState Body(NodeId node) const override;
  // A sample one of the node's sensors took on its own clock: logged as a reading at its time.
  void Sampled(NodeId node, const sensors::SensorSet::Sample& sample);
  std::vector<NodeId> RadioNeighbours(NodeId node) const override;
  std::vector<MessageInFlight> MessagesInFlight() const override { return transport_->InFlight(); }
  std::string ControllerState(NodeId node) const override { return states_.at(node); }

 private:
  void BuildBodies();
  void AddBody(const NodeSpec& node);
  void BuildTransport();
  void BuildNodes(hosting::Registry& registry);
  void AddNode(NodeId id, std::unique_ptr<Controller> controller);
  void AddBattery(NodeId id);
  void Die(NodeId id);     // its battery reached the cutoff
  void Revive(NodeId id);  // a dead node's battery was recharged
  void Receive(NodeId to, const Message& message);
  void Lost(NodeId to, const Message& message, const std::string& why);
  template <typename Event>
  void Tell(const Event& event) {
    if (running_) bus_.Publish(event);
  }
  double Now() const;  // s, simulated
  hosting::ControllerHost::Hooks HostHooks(NodeId id);
  void FollowBody(NodeId id, net::BodyMobilityModel* mobility);  // its radio, from its body's pose now

  const RunSpec spec_;
  sensors::Surroundings surroundings_;      // of spec_, with the bodies as cameras see them once they exist
  std::optional<Calibration> calibration_;  // the abstract radio's, measured or cached
  RunNodes run_nodes_;
  const RobotDrivers drivers_;
  std::unique_ptr<physics::PipelinedWorld> physics_;
  std::vector<std::unique_ptr<robots::NodeModel>> models_;
  std::vector<std::unique_ptr<sensors::SensorSet>> sensors_;
  std::unique_ptr<PosePipeline> poses_;
  std::unique_ptr<MessageLedger> transport_;
  net::WirelessNetwork* wireless_ = nullptr;  // the inner transport, when it is ns-3's network
  net::LocalTransport* local_ = nullptr;      // or when it is the local stand-in
  std::unique_ptr<hosting::HostClock> clock_;
  std::vector<std::unique_ptr<hosting::SimulatedNode>> nodes_;
  std::vector<std::unique_ptr<hosting::ControllerHost>> hosts_;
  RunBus bus_;
  bool running_ = false;
  RemoteInbox remote_inbox_;
  std::vector<std::string> states_;  // per node: the state of its controller's last transition
  NodeBatteries batteries_;
  std::vector<bool> off_for_good_;  // per node: switched off (by an event), not dead
};

}  // namespace sanet::sim
