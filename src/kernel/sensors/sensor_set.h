// The sensors of one node, made from its model's sensor configurations by their kinds, and read
// by instance name. Both paths that read a simulated robot's sensors (its controller through
// hosting::SimulatedNode, a front end through sim::Driver) come here.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sensors/sampling_sensor.h"
#include "sensors/sensor_kind.h"

namespace sanet::sensors {

class SensorSet {
 public:
  // Each instance draws its noise from the stream `stream_prefix`/<instance name> of `seed`.
  // `surroundings` outlives the set.
  SensorSet(physics::PhysicsWorld& world, const robots::NodeModel& model, const Pose2D& start, std::uint64_t seed,
            const std::string& stream_prefix, const Surroundings& surroundings, NodeId self);

  // The instances' names, in the order front ends present them (PresentationOrder).
  const std::vector<std::string>& names() const { return names_; }
  bool Has(const std::string& name) const { return Find(name) != nullptr; }
  // The kind of instance `name`; "" for none.
  std::string KindOf(const std::string& name) const;
  // Empty when there is no such instance or it has nothing to say.
  std::optional<SensorReading> Read(const std::string& name, const ReadContext& context);
  // When instance `name`'s last reading was taken, if it samples on its own clock.
  std::optional<double> SampledAt(const std::string& name) const;
  void AfterPhysicsStep(double time);
  // A sample of a sensor that samples on its own clock; the names live as long as the set.
  struct Sample {
    const std::string *instance, *kind;
    TimedReading taken;
  };
  // Every sample due by `time` of the sensors that sample on their own clocks.
  void SampleOwnClocks(double time);
  // The samples its sensors took on their own clocks since the last call, instance by instance.
  void TakeSamples(std::vector<Sample>& out);
  bool SamplesOnItsOwn() const { return !samplers_.empty(); }  // some sensor does

 private:
  struct Entry {
    std::string name, kind;
    std::unique_ptr<SensorInstance> instance;
  };
  const Entry* Find(const std::string& name) const;
  std::vector<Entry> entries_;
  std::vector<std::string> names_;
  std::vector<SamplingSensor*> samplers_;  // the instances that sample on their own clocks
  std::vector<TimedReading> taken_;        // reused
};

}  // namespace sanet::sensors
