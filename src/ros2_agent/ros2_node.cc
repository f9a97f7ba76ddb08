#include "ros2_agent/ros2_node.h"

#include <algorithm>

#include "robots/kinematics.h"
#include "robots/node_model.h"

namespace sanet::ros2agent {

Ros2Node::Ros2Node(const sim::RunSpec& spec, NodeId id, Ros2Robot& robot, hil::PeerSocket& peers, AgentRecord& record,
                   std::function<double()> clock)
    : spec_(spec),
      id_(id),
      robot_(robot),
      peers_(peers),
      record_(record),
      clock_(std::move(clock)),
      random_(spec.seed, "node/" + spec.nodes.at(id).name + "/controller") {
  hil::LoopNetworkView::Hooks hooks{[this] { return Now(); }, [this] { return peers_.Addresses(); },
                                    [this](const std::string& text) { Log(text); },
                                    [this](const std::string& name) { return Lookup(name); }};
  view_ = std::make_unique<hil::LoopNetworkView>(spec_, id_, nullptr, std::move(hooks));  // the kernel's
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
    peers_.Send(to, hil::AgentDatagram::kUnicast, payload);
  else
    ++to_nowhere_;
}

// Every other robot's agent gets its copy; there is nothing else to reach without a simulator.
void Ros2Node::ToEveryAgent(Delivery delivery, const Bytes& payload) {
  ++messages_sent_;
  record_.Sent(ClockNow(), kBroadcast, delivery, payload.size());
  for (NodeId to = 0; to < spec_.nodes.size(); ++to)
    if (to != id_ && HasAgent(to)) peers_.Send(to, hil::AgentDatagram::kBroadcast, payload);
}

void Ros2Node::Broadcast(const Bytes& payload) { ToEveryAgent(Delivery::kBroadcast, payload); }
void Ros2Node::Flood(const Bytes& payload) { ToEveryAgent(Delivery::kFlood, payload); }

// As the simulated node: within the model's limits, then cmd_vel (x forward, y left, z up).
bool Ros2Node::ApplyDrive(const Twist2D& v) {
  const robots::ModelSpec& model = spec_.nodes[id_].model;
  if (model.kind == robots::ModelKind::kMote) return false;
  robot_.Drive(robots::LimitDrive(model, v), ClockNow());
  return true;
}

// A differential drive's wheel speeds as the body's motion (ROS 2 robots take cmd_vel).
bool Ros2Node::ApplyWheelSpeeds(const std::vector<double>& w) {
  const robots::ModelSpec& model = spec_.nodes[id_].model;
  if (model.kind != robots::ModelKind::kDiffDrive || w.size() != 2) return false;
  robot_.Drive(robots::DiffDriveKinematics(model.diffdrive.axle_length, model.diffdrive.wheel_radius).BodyTwist(w),
               ClockNow());
  return true;
}

}  // namespace sanet::ros2agent
