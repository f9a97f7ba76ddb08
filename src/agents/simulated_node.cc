#include "agents/simulated_node.h"

namespace sanet::agents {

std::optional<BearingReading> SimulatedNode::Bearing(NodeId target) {
  if (target >= directory_.NodeCount() || target == id_) return std::nullopt;
  return model_.Bearing(directory_.TruePose(target));
}

void SimulatedNode::SwitchOff() {
  model_.Drive({});
  off_ = true;
  transport_.SwitchOff(id_);
}

}  // namespace sanet::agents
