// A kind of sensor as the simulation kernel knows it: what it is (for `sanet list`), where a
// model carries it by default and with which settings, and how one instance on a node reads the
// world. Each kind is one folder, sensors/<kind>/, registered once in sensors/sensor_kinds.h;
// its other layers' parts (scenario fields, USARSim lines, ROS 2 messages) sit beside it.
#pragma once

#include <any>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/random_stream.h"
#include "physics/physics_world.h"
#include "robots/node_model.h"
#include "sanet/readings.h"
#include "sensors/surroundings.h"

namespace sanet::sensors {

// What `sanet list --sensors` says of a kind.
struct SensorInfo {
  std::string name;       // the kind's name, and its default instance's
  std::string summary;    // what it measures, in a line
  std::string reading;    // the C++ reading type (sanet/readings.h) Node::Sensor gives
  std::string units;      // of the reading's fields
  std::string ros2_type;  // the ROS 2 message it is published as ("" if none)
  std::string topic;      // its default instance's topic under /<robot>
};

// What a read may look at besides its own node: the other nodes, and a target when the read is
// aimed at one node (Node::Bearing).
struct ReadContext {
  NodeId self = 0;
  std::size_t node_count = 0;
  std::function<Pose2D(NodeId)> true_pose;
  std::optional<NodeId> target;
  std::function<std::optional<BatteryReading>()> battery;  // empty without a battery
  double time = 0;                                         // s, simulated: when the reading is taken
};

// A sample a sensor took on its own clock, at `t` (s, simulated).
struct TimedReading {
  double t = 0;
  SensorReading reading;
};

// One sensor on one node.
class SensorInstance {
 public:
  virtual ~SensorInstance() = default;
  // Empty when the sensor has nothing to say (a target out of range).
  virtual std::optional<SensorReading> Read(const ReadContext& context) = 0;
  // After every physics step of a moving node, the step ending at `time` (s, simulated): for
  // sensors that integrate (odometry) or sample on their own clock (the IMU).
  virtual void AfterPhysicsStep(double /*time*/) {}
  // The samples taken on the sensor's own clock since the last call, oldest first (a kind that
  // SamplesOnItsOwn; others take none): the run logs each one.
  virtual void TakeSamples(std::vector<TimedReading>& /*out*/) {}
  // When the reading the last read got was taken (s, simulated), for a sensor that samples on its
  // own clock: a read gets the latest sample, which may be older than the read.
  virtual std::optional<double> SampledAt() const { return std::nullopt; }
};

// Where an instance sits and what it draws its noise from.
struct Mount {
  physics::PhysicsWorld& world;
  const robots::NodeModel& model;
  Pose2D start;         // the node's pose when the run began
  RandomStream random;  // the instance's own stream
  const Surroundings& surroundings;
  NodeId self = 0;  // the node it is on
};

class SensorKind {
 public:
  virtual ~SensorKind() = default;
  virtual const SensorInfo& Info() const = 0;
  // The settings of the kind on `model` when the scenario gives none (or says `true`).
  virtual std::any DefaultSettings(const robots::ModelSpec& model) const = 0;
  // Whether a scenario may take the kind's default instance off a node (`ground_truth: false` is
  // refused: front ends report every robot's pose).
  virtual bool Removable() const { return true; }
  // Why the kind cannot sit on `model` ("a mote has no wheels, so no odometry"); empty if it can.
  virtual std::optional<std::string> Refuses(const robots::ModelSpec& /*model*/) const { return std::nullopt; }
  // Why the kind cannot work in a world of these surroundings ("a fix needs world.datum").
  virtual std::optional<std::string> RefusesWorld(const Surroundings& /*world*/) const { return std::nullopt; }
  virtual std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const = 0;
  // Whether an instance samples on its own clock (an IMU, a satellite fix): the run logs its
  // samples as it takes them (TakeSamples), not the readings a controller takes of them.
  virtual bool SamplesOnItsOwn() const { return false; }
};

}  // namespace sanet::sensors
