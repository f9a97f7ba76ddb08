// A sensor that samples on its own clock (an IMU, a satellite fix; SensorKind::SamplesOnItsOwn):
// a sample every 1/rate s of simulated time, whether or not anyone reads. Samples are taken after
// each physics step of the moving body and at each read (a body at rest has no steps); a read
// gets the latest sample at or before its time. Each sample is kept until the run takes it to
// log (TakeSamples).
#pragma once

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

 protected:
  // The sample due now, `period` s after the previous one.
  virtual SensorReading Sample(double period) = 0;

 private:
  void SampleUntil(double time);

  const double period_;  // s
  physics::PhysicsWorld& world_;
  double next_ = 0;  // s, when the next sample is due
  std::optional<SensorReading> latest_;
  std::vector<TimedReading> unsent_;  // not yet taken to log
};

}  // namespace sanet::sensors
