// The node a controller sees on a ROS 2 robot (`sanet agent --ros2`): its readings and motion
// through the robot's topics (ros2_robot.h), messages to the other robots' agents over UDP
// (usarsim_agent::PeerSocket, authenticated with the team's key), the host kernel's routing view, the
// robot's clock, and what it records kept in the agent's own folder (agent_record.h). Without a
// simulator there are no motes and no bearing sensor: messages to a node without an agent go
// nowhere (counted), Bearing() is empty. The controller cannot tell it from the other nodes.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/random_stream.h"
#include "ros2_agent/agent_record.h"
#include "ros2_agent/ros2_robot.h"
#include "sanet/node.h"
#include "sim/run_spec.h"
#include "usarsim_agent/loop_network_view.h"
#include "usarsim_agent/peer_socket.h"

namespace sanet::ros2_agent {

class Ros2Node : public Node {
 public:
  // `clock`: the robot's time, s (its /clock with use_sim_time, else this computer's from the
  // team's start).
  Ros2Node(const sim::RunSpec& spec, NodeId id, Ros2Robot& robot, usarsim_agent::PeerSocket& peers, AgentRecord& record,
           std::function<double()> clock);

  // Inside a control step, Now() is the step's time on the grid, as in every mode.
  void SetStepTime(std::optional<double> t) { step_time_ = t; }
  double ClockNow() const { return clock_(); }
  std::uint64_t messages_sent() const { return messages_sent_; }
  std::uint64_t messages_to_nowhere() const { return to_nowhere_; }

  double Now() const override { return step_time_ ? *step_time_ : clock_(); }
  NodeId Id() const override { return id_; }
  const std::string& Name() const override { return spec_.nodes[id_].name; }
  std::optional<NodeId> Lookup(const std::string& name) const override;
  std::string NameOf(NodeId id) const override { return id < spec_.nodes.size() ? spec_.nodes[id].name : ""; }
  std::size_t NodeCount() const override { return spec_.nodes.size(); }
  // The robot's topics: its IR sensors, laser, odometry and ground truth.
  std::optional<SensorReading> Sensor(const std::string& name) override;
  std::optional<BearingReading> Bearing(NodeId) override { return std::nullopt; }
  // The robot's own radio is not the controller's to switch.
  bool SetRadioSleep(bool) override {
    Log("radio sleep refused: a ROS 2 robot's radio is its own, not sanet's");
    return false;
  }
  bool Holonomic() const override { return robots::Holonomic(spec_.nodes[id_].model); }
  void Send(NodeId to, const Bytes& payload) override;
  void Broadcast(const Bytes& payload) override;
  void Flood(const Bytes& payload) override;
  NetworkView& Network() override { return *view_; }
  double Random() override { return random_.Uniform(); }
  void Log(const std::string& text) override { record_.Log(Now(), text); }
  void Transition(const std::string& from, const std::string& to, const std::string& why) override {
    record_.Transition(Now(), from, to, why);
  }
  void Metric(const std::string& name, double value) override { record_.Metric(Now(), name, value); }

 protected:
  bool ApplyDrive(const Twist2D& velocity) override;
  bool ApplyWheelSpeeds(const std::vector<double>& rad_per_s) override;

 private:
  bool HasAgent(NodeId node) const { return sim::RunsAsAgent(spec_.nodes.at(node)); }
  void ToEveryAgent(Delivery delivery, const Bytes& payload);

  const sim::RunSpec& spec_;
  NodeId id_;
  Ros2Robot& robot_;
  usarsim_agent::PeerSocket& peers_;
  AgentRecord& record_;
  std::function<double()> clock_;
  std::unique_ptr<usarsim_agent::LoopNetworkView> view_;
  RandomStream random_;
  std::optional<double> step_time_;
  std::uint64_t messages_sent_ = 0, to_nowhere_ = 0;
};

}  // namespace sanet::ros2_agent
