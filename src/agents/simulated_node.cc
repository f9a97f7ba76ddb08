#include "agents/simulated_node.h"

namespace sanet::agents {

std::optional<BearingReading> SimulatedNode::Bearing(NodeId target) {
  if (target >= directory_.NodeCount() || target == id_) return std::nullopt;
  return model_.Bearing(directory_.TruePose(target));
}

bool SimulatedNode::ApplyDrive(const Twist2D& velocity) { return !off_ && model_.Drive(velocity); }

bool SimulatedNode::ApplyWheelSpeeds(const std::vector<double>& w) { return !off_ && model_.SetWheelSpeeds(w); }

void SimulatedNode::SwitchOff() {
  model_.Drive({});
  off_ = true;
  transport_.SwitchOff(id_);
}

}  // namespace sanet::agents
