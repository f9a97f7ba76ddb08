#include "hosting/simulated_node.h"

namespace sanet::hosting {

sensors::ReadContext SimulatedNode::Context(std::optional<NodeId> target) const {
  return {id_,
          directory_.NodeCount(),
          [this](NodeId node) { return directory_.TruePose(node); },
          target,
          [this] { return directory_.Battery(id_); },
          Now()};
}

std::optional<SensorReading> SimulatedNode::Sensor(const std::string& name) {
  if (!sensors_.Has(name)) return std::nullopt;
  std::optional<SensorReading> reading = sensors_.Read(name, Context());
  last_.time = Now();
  last_.readings[name] = reading;
  if (reading) directory_.ReadSensor(id_, name, sensors_.KindOf(name), *reading);
  return reading;
}

// The default bearing sensor aimed at one node: one draw of noise, for that node only.
std::optional<BearingReading> SimulatedNode::Bearing(NodeId target) {
  if (target >= directory_.NodeCount() || target == id_ || sensors_.KindOf("bearing") != "bearing") return std::nullopt;
  const std::optional<SensorReading> reading = sensors_.Read("bearing", Context(target));
  const auto* bearings = reading ? std::get_if<BearingsReading>(&*reading) : nullptr;
  if (!bearings || bearings->in_range.empty()) return std::nullopt;
  return bearings->in_range.front().reading;
}

bool SimulatedNode::SetRadioSleep(bool asleep) {
  if (off_) {
    Log("radio sleep refused: the node is switched off (its radio with it)");
    return false;
  }
  if (transport_.SetSleep(id_, asleep)) return true;
  Log("radio sleep refused: this node's radio does not sleep (the run has no `network` section, or its radio is "
      "the abstract one)");
  return false;
}

bool SimulatedNode::ApplyDrive(const Twist2D& velocity) { return !off_ && model_.Drive(velocity); }

bool SimulatedNode::ApplyWheelSpeeds(const std::vector<double>& w) { return !off_ && model_.SetWheelSpeeds(w); }

void SimulatedNode::SwitchOff() {
  model_.Drive({});
  off_ = true;
  transport_.SwitchOff(id_);
}

void SimulatedNode::SwitchOn() {
  if (!off_) return;
  off_ = false;
  transport_.SwitchOn(id_);
}

bool SimulatedNode::Fits(const Bytes& payload) {
  if (payload.size() <= net::kMostMessageBytes) return true;
  if (!said_too_large_)
    Log("message of " + std::to_string(payload.size()) + " bytes refused: a message holds at most " +
        std::to_string(net::kMostMessageBytes) +
        " bytes (one UDP datagram less sanet's header); split it (said once: "
        "later ones are refused too)");
  said_too_large_ = true;
  return false;
}

}  // namespace sanet::hosting
