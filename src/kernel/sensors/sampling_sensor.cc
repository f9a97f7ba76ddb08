#include "sensors/sampling_sensor.h"

namespace sanet::sensors {

std::optional<SensorReading> SamplingSensor::Read(const ReadContext& context) {
  world_.Settle();
  SampleUntil(context.time);
  return latest_;
}

void SamplingSensor::TakeSamples(std::vector<TimedReading>& out) {
  for (TimedReading& r : unsent_) out.push_back(std::move(r));
  unsent_.clear();
}

void SamplingSensor::SampleUntil(double time) {
  // Each due time a whole number of periods from 0, so that they do not drift.
  for (double due = taken_ * period_; due <= time + 1e-9; due = ++taken_ * period_) {
    latest_ = Sample(period_);
    latest_at_ = due;
    unsent_.push_back({due, *latest_});
  }
}

}  // namespace sanet::sensors
