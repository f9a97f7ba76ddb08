// The sensors of one node, made from its model's sensor configurations by their kinds, and read
// by instance name. Both paths that read a simulated robot's sensors (its controller through
// hosting::SimulatedNode, a front end through sim::Driver) come here.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sensors/sensor_kind.h"

namespace sanet::sensors {

class SensorSet {
 public:
  // Each instance draws its noise from the stream `stream_prefix`/<instance name> of `seed`.
  SensorSet(physics::PhysicsWorld& world, const robots::NodeModel& model, const Pose2D& start, std::uint64_t seed,
            const std::string& stream_prefix);

  // The instances' names, in the order front ends present them (PresentationOrder).
  const std::vector<std::string>& names() const { return names_; }
  bool Has(const std::string& name) const { return Find(name) != nullptr; }
  // The kind of instance `name`; "" for none.
  std::string KindOf(const std::string& name) const;
  // Empty when there is no such instance or it has nothing to say.
  std::optional<SensorReading> Read(const std::string& name, const ReadContext& context);
  void AfterPhysicsStep(double time);

 private:
  struct Entry {
    std::string name, kind;
    std::unique_ptr<SensorInstance> instance;
  };
  const Entry* Find(const std::string& name) const;
  std::vector<Entry> entries_;
  std::vector<std::string> names_;
};

}  // namespace sanet::sensors
