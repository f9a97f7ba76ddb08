// The node a controller sees in a simulated run: physics model, simulation clock and the
// run's transport behind the portable interface. Every driver of a simulated robot goes
// through it (its controller, or a protocol client of the server), so that the rules of the
// run, such as switch-off, hold for all of them.
#pragma once

#include <string>

#include "agents/host_clock.h"
#include "core/random_stream.h"
#include "net/transport.h"
#include "robots/node_model.h"
#include "sanet/node.h"

namespace sanet::agents {

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
  // What a node's driver read, now, for the run's log: readings are recorded as taken, never read
  // again (a noisy sensor draws from the node's random stream).
  enum class Scanner { kIr, kLaser };
  virtual void ReadScan(NodeId /*node*/, Scanner /*which*/, const RangeScan& /*scan*/) {}
  virtual void ReadOdometry(NodeId /*node*/, const Pose2D& /*pose*/) {}
};

class SimulatedNode : public Node {
 public:
  SimulatedNode(NodeId id, std::string name, robots::NodeModel& model, net::Transport& transport,
                NodeDirectory& directory, const HostClock& clock, RandomStream random)
      : id_(id),
        name_(std::move(name)),
        model_(model),
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

  // Each read is also kept (LastReads), for a script that looks at the run between steps.
  std::optional<RangeScan> Ir() override { return Told(NodeDirectory::Scanner::kIr, Kept(last_.ir, model_.Ir())); }
  std::optional<RangeScan> Laser() override {
    return Told(NodeDirectory::Scanner::kLaser, Kept(last_.laser, model_.Laser()));
  }
  std::optional<Pose2D> Odometry() override {
    std::optional<Pose2D> pose = Kept(last_.odometry, model_.Odometry());
    if (pose) directory_.ReadOdometry(id_, *pose);
    return pose;
  }
  std::optional<Pose2D> GroundTruth() override { return Kept(last_.ground_truth, model_.GroundTruth()); }

  // What the node's controller read last, and when (-1: never); reading this draws no noise.
  struct LastReads {
    double time = -1;
    std::optional<RangeScan> ir, laser;
    std::optional<Pose2D> odometry, ground_truth;
  };
  const LastReads& last_reads() const { return last_; }
  std::optional<BearingReading> Bearing(NodeId target) override;

  bool Holonomic() const override { return model_.holonomic(); }

  // A switched-off node's radio is off: it sends nothing.
  void Send(NodeId to, const Bytes& payload) override {
    if (!off_) transport_.Send(id_, to, payload);
  }
  void Broadcast(const Bytes& payload) override {
    if (!off_) transport_.Broadcast(id_, payload);
  }
  void Flood(const Bytes& payload) override {
    if (!off_) transport_.Flood(id_, payload);
  }
  NetworkView& Network() override { return transport_.View(id_); }
  void Log(const std::string& text) override { directory_.Log(id_, text); }
  void Transition(const std::string& from, const std::string& to, const std::string& why) override {
    directory_.Transition(id_, from, to, why);
  }
  void Metric(const std::string& name, double value) override { directory_.Metric(id_, name, value); }
  double Random() override { return random_.Uniform(); }

  // The node stops for good: motors, radio (and, through its host, its controller).
  void SwitchOff();
  bool switched_off() const { return off_; }
  robots::NodeModel& model() { return model_; }
  const robots::NodeModel& model() const { return model_; }

 protected:
  // A switched-off node does not move, whoever asks (Node refused commands that are not numbers).
  bool ApplyDrive(const Twist2D& velocity) override;
  bool ApplyWheelSpeeds(const std::vector<double>& w) override;

 private:
  template <typename T>
  std::optional<T> Kept(std::optional<T>& slot, std::optional<T> value) {
    last_.time = Now();
    slot = value;
    return value;
  }
  std::optional<Pose2D> Kept(std::optional<Pose2D>& slot, Pose2D value) { return Kept(slot, std::optional(value)); }
  std::optional<RangeScan> Told(NodeDirectory::Scanner which, std::optional<RangeScan> scan) {
    if (scan) directory_.ReadScan(id_, which, *scan);
    return scan;
  }
  LastReads last_;

  NodeId id_;
  std::string name_;
  robots::NodeModel& model_;
  net::Transport& transport_;
  NodeDirectory& directory_;
  const HostClock& clock_;
  RandomStream random_;
  bool off_ = false;
};

}  // namespace sanet::agents
