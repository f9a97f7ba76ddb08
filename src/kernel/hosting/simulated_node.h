// The node a controller sees in a simulated run: physics model, simulation clock and the
// run's transport behind the portable interface. Every driver of a simulated robot goes
// through it (its controller, or a protocol client of the server), so that the rules of the
// run, such as switch-off, hold for all of them.
#pragma once

#include <map>
#include <string>

#include "core/random_stream.h"
#include "hosting/host_clock.h"
#include "net/transport.h"
#include "robots/node_model.h"
#include "sanet/node.h"
#include "sensors/sensor_set.h"

namespace sanet::hosting {

// What a node may ask of the run it belongs to.
class NodeDirectory {
 public:
  virtual ~NodeDirectory() = default;
  virtual std::optional<NodeId> Lookup(const std::string& name) const = 0;
  virtual std::string NameOf(NodeId id) const = 0;
  virtual std::size_t NodeCount() const = 0;
  virtual Pose2D TruePose(NodeId node) const = 0;
  virtual void Log(NodeId node, const std::string& text) = 0;
  virtual void Transition(NodeId node, const std::string& from, const std::string& to, const std::string& why) = 0;
  virtual void Metric(NodeId node, const std::string& name, double value) = 0;
  // What a node's driver read, now, from its sensor `instance` of `kind`, for the run's log:
  // readings are recorded as taken, never read again (a noisy sensor draws from the node's
  // random stream).
  virtual void ReadSensor(NodeId /*node*/, const std::string& /*instance*/, const std::string& /*kind*/,
                          const SensorReading& /*reading*/) {}
  // The node's battery now; empty for a node with an infinite supply.
  virtual std::optional<BatteryReading> Battery(NodeId /*node*/) const { return std::nullopt; }
};

class SimulatedNode : public Node {
 public:
  SimulatedNode(NodeId id, std::string name, robots::NodeModel& model, sensors::SensorSet& sensors,
                net::Transport& transport, NodeDirectory& directory, const HostClock& clock, RandomStream random)
      : id_(id),
        name_(std::move(name)),
        model_(model),
        sensors_(sensors),
        transport_(transport),
        directory_(directory),
        clock_(clock),
        random_(random) {}

  double Now() const override { return clock_.Now(); }
  NodeId Id() const override { return id_; }
  const std::string& Name() const override { return name_; }
  std::optional<NodeId> Lookup(const std::string& name) const override { return directory_.Lookup(name); }
  std::string NameOf(NodeId id) const override { return directory_.NameOf(id); }
  std::size_t NodeCount() const override { return directory_.NodeCount(); }

  // Each read is told to the run (NodeDirectory::ReadSensor) and kept (LastReads), for a script
  // that looks at the run between steps.
  std::optional<SensorReading> Sensor(const std::string& name) override;
  std::optional<BearingReading> Bearing(NodeId target) override;

  // What the node's driver read last from each sensor, and when (-1: never); reading this draws
  // no noise.
  struct LastReads {
    double time = -1;
    std::map<std::string, std::optional<SensorReading>> readings;  // by instance
  };
  const LastReads& last_reads() const { return last_; }
  sensors::SensorSet& sensors() { return sensors_; }

  bool Holonomic() const override { return model_.holonomic(); }

  // A switched-off node's radio is off: it sends nothing. A message past one UDP datagram is
  // refused, with or without a network, and the node's log says why.
  void Send(NodeId to, const Bytes& payload) override {
    if (!off_ && Fits(payload)) transport_.Send(id_, to, payload);
  }
  void Broadcast(const Bytes& payload) override {
    if (!off_ && Fits(payload)) transport_.Broadcast(id_, payload);
  }
  void Flood(const Bytes& payload) override {
    if (!off_ && Fits(payload)) transport_.Flood(id_, payload);
  }
  NetworkView& Network() override { return transport_.View(id_); }
  bool SetRadioSleep(bool asleep) override;
  void Log(const std::string& text) override { directory_.Log(id_, text); }
  void Transition(const std::string& from, const std::string& to, const std::string& why) override {
    directory_.Transition(id_, from, to, why);
  }
  void Metric(const std::string& name, double value) override { directory_.Metric(id_, name, value); }
  double Random() override { return random_.Uniform(); }

  // The node stops for good: motors, radio (and, through its host, its controller).
  void SwitchOff();
  void SwitchOn();  // back from a switch-off: its radio and drive work again
  bool switched_off() const { return off_; }
  robots::NodeModel& model() { return model_; }
  const robots::NodeModel& model() const { return model_; }

 protected:
  // A switched-off node does not move, whoever asks (Node refused commands that are not numbers).
  bool ApplyDrive(const Twist2D& velocity) override;
  bool ApplyWheelSpeeds(const std::vector<double>& w) override;

 private:
  bool Fits(const Bytes& payload);
  bool said_too_large_ = false;
  sensors::ReadContext Context(std::optional<NodeId> target = std::nullopt) const;
  LastReads last_;

  NodeId id_;
  std::string name_;
  robots::NodeModel& model_;
  sensors::SensorSet& sensors_;
  net::Transport& transport_;
  NodeDirectory& directory_;
  const HostClock& clock_;
  RandomStream random_;
  bool off_ = false;
};

}  // namespace sanet::hosting
