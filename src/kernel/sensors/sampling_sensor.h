// A sensor that samples on its own clock (an IMU, a satellite fix; SensorKind::SamplesOnItsOwn):
// a sample every 1/rate s of simulated time, whether or not anyone reads or the body moves. The
// samples due during a physics step are taken at its end (the run calls SampleUntil for every
// node with such a sensor), and a read takes those due by its time; so a read gets the latest
// sample taken, which may be due up to one physics step after the read's time when the step in
// flight has ended. Each sample is kept until the run takes it to log (TakeSamples).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sensors/sensor_kind.h"

namespace sanet::sensors {

class SamplingSensor : public SensorInstance {
 public:
  SamplingSensor(double rate, physics::PhysicsWorld& world) : period_(1 / rate), world_(world) {}
  std::optional<SensorReading> Read(const ReadContext& context) final;
  void AfterPhysicsStep(double time) final { SampleUntil(time); }
  void TakeSamples(std::vector<TimedReading>& out) final;
  std::optional<double> SampledAt() const final { return latest_at_; }
  // Takes every sample due by `time` (s, simulated).
  void SampleUntil(double time);

 protected:
  // The sample due now, `period` s after the previous one.
  virtual SensorReading Sample(double period) = 0;

 private:
  const double period_;  // s
  physics::PhysicsWorld& world_;
  std::uint64_t taken_ = 0;  // samples so far: the next is due at taken_ * period_
  std::optional<SensorReading> latest_;
  std::optional<double> latest_at_;   // s: when latest_ was due
  std::vector<TimedReading> unsent_;  // not yet taken to log
};

}  // namespace sanet::sensors
