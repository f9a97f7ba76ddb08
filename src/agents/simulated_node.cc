#include "agents/simulated_node.h"

namespace sanet::agents {

std::optional<BearingReading> SimulatedNode::Bearing(NodeId target) {
  if (target >= directory_.NodeCount() || target == id_) return std::nullopt;
  return model_.Bearing(directory_.TruePose(target));
}

bool SimulatedNode::Drive(const Twist2D& velocity) {
  if (off_) return false;
  if (robots::Finite({velocity.vx, velocity.vy, velocity.omega})) return model_.Drive(velocity);
  Log("drive refused: a velocity that is not a finite number (the motors keep their last command)");
  return false;
}

bool SimulatedNode::SetWheelSpeeds(const std::vector<double>& w) {
  if (off_) return false;
  if (robots::Finite(w)) return model_.SetWheelSpeeds(w);
  Log("wheel speeds refused: a speed that is not a finite number (the motors keep their last command)");
  return false;
}

void SimulatedNode::SwitchOff() {
  model_.Drive({});
  off_ = true;
  transport_.SwitchOff(id_);
}

}  // namespace sanet::agents
