// What the nodes of a run report while it goes, to whoever runs it (the stepper records them
// through the outputs and applies the end conditions).
#pragma once

#include <string>

#include "agents/simulated_node.h"
#include "sanet/message.h"
#include "sim/snapshot.h"

namespace sanet::sim {

class RunEvents {
 public:
  virtual ~RunEvents() = default;
  virtual void Log(NodeId node, const std::string& text) = 0;
  virtual void Transition(NodeId node, const std::string& from, const std::string& to, const std::string& why) = 0;
  virtual void Metric(NodeId node, const std::string& name, double value) = 0;
  virtual void Delivered(NodeId to, const Message& message) = 0;
  virtual void DroppedByImpairment(NodeId to, const Message& message) = 0;
  virtual void Lost(NodeId to, const Message& message, const std::string& why) = 0;
  virtual void Failed(const std::string& why) = 0;
  // A node joined the running world (a robot a front end spawned, as the class it names).
  virtual void Spawned(NodeId node, const std::string& spawned_as) = 0;
  // What a node's driver read (agents::NodeDirectory), with where the body truly is now.
  virtual void ReadSensor(NodeId /*node*/, const std::string& /*instance*/, const std::string& /*kind*/,
                          const SensorReading& /*reading*/, const BodyState& /*body*/) {}
};

}  // namespace sanet::sim
