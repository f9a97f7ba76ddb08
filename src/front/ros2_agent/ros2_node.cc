#include "ros2_agent/ros2_node.h"

#include <algorithm>

#include "robots/kinematics.h"
#include "robots/node_model.h"

namespace sanet::ros2_agent {

Ros2Node::Ros2Node(const sim::RunSpec& spec, NodeId id, Ros2Robot& robot, usarsim_agent::PeerSocket& peers,
                   AgentRecord& record, std::function<double()> clock)
    : spec_(spec),
      id_(id),
      robot_(robot),
      peers_(peers),
      record_(record),
      clock_(std::move(clock)),
      random_(spec.seed, "node/" + spec.nodes.at(id).name + "/controller") {
  usarsim_agent::LoopNetworkView::Hooks hooks{[this] { return Now(); }, [this] { return peers_.Addresses(); },
                                              [this](const std::string& text) { Log(text); },
                                              [this](const std::string& name) { return Lookup(name); }};
  view_ = std::make_unique<usarsim_agent::LoopNetworkView>(spec_, id_, nullptr, std::move(hooks));  // the kernel's
}

std::optional<NodeId> Ros2Node::Lookup(const std::string& name) const {
  for (NodeId i = 0; i < spec_.nodes.size(); ++i)
    if (spec_.nodes[i].name == name) return i;
  return std::nullopt;
}

void Ros2Node::Send(NodeId to, const Bytes& payload) {
  if (to >= spec_.nodes.size() || to == id_) return;
  ++messages_sent_;
  record_.Sent(ClockNow(), to, Delivery::kUnicast, payload.size());
  if (HasAgent(to))
    peers_.Send(to, wire::AgentDatagram::kUnicast, payload);
  else
    ++to_nowhere_;
}

// Every other robot's agent gets its copy; there is nothing else to reach without a simulator.
void Ros2Node::ToEveryAgent(Delivery delivery, const Bytes& payload) {
  ++messages_sent_;
  record_.Sent(ClockNow(), kBroadcast, delivery, payload.size());
  for (NodeId to = 0; to < spec_.nodes.size(); ++to)
    if (to != id_ && HasAgent(to)) peers_.Send(to, wire::AgentDatagram::kBroadcast, payload);
}

void Ros2Node::Broadcast(const Bytes& payload) { ToEveryAgent(Delivery::kBroadcast, payload); }
void Ros2Node::Flood(const Bytes& payload) { ToEveryAgent(Delivery::kFlood, payload); }

// As the simulated node: within the model's limits, then cmd_vel (x forward, y left, z up).
std::optional<SensorReading> Ros2Node::Sensor(const std::string& name) {
  const auto as_reading = [](const auto& value) { return value ? std::optional<SensorReading>(*value) : std::nullopt; };
  if (name == "ground_truth") return as_reading(robot_.GroundTruth());
  if (name == "odometry") return as_reading(robot_.Odometry());
  if (name == "laser") return as_reading(robot_.Laser());
  if (name == "ir") return as_reading(robot_.Ir());
  return std::nullopt;
}

bool Ros2Node::ApplyDrive(const Twist2D& v) {
  const robots::ModelSpec& model = spec_.nodes[id_].model;
  if (!robots::HasDrive(model)) return false;
  robot_.Drive(robots::LimitDrive(model, v), ClockNow());
  return true;
}

// Wheel speeds as the body's motion, through the model's kinematics (ROS 2 robots take cmd_vel).
bool Ros2Node::ApplyWheelSpeeds(const std::vector<double>& w) {
  const robots::ModelSpec& model = spec_.nodes[id_].model;
  const std::unique_ptr<robots::Kinematics> kinematics = model.model().MakeKinematics(model);
  if (!kinematics || w.size() != kinematics->WheelSpeeds({}).size()) return false;
  robot_.Drive(kinematics->BodyTwist(w), ClockNow());
  return true;
}

}  // namespace sanet::ros2_agent
