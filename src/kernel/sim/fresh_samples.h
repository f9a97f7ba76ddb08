// Which of a robot's readings carry a sample a front end has not yet sent. A sensor that samples
// on its own clock (a camera at 5 Hz, an IMU) gives its latest sample at every read, so that a
// front end reading at 10 Hz would send a 5 Hz camera's picture twice; each front end that sends
// readings (the ROS 2 face, the robot server's SEN lines) keeps one of these per robot and sends
// a sample once. A sample due in the physics step in flight (up to one step after the read, see
// sensors/sampling_sensor.h) waits for the next read, so that nothing sent is stamped ahead of
// the read's time.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "sim/driver.h"

namespace sanet::sim {

class FreshSamples {
 public:
  // Whether instance `instance`'s reading in `readings` is to be sent now (it is then counted as
  // sent). Readings of sensors read at the read's time (not sampled) always are.
  bool TakeIfNew(const std::string& instance, const SensorReadings& readings) {
    const std::optional<double> at = readings.SampledAt(instance);
    if (!at) return true;
    if (*at > readings.time + 1e-9) return false;
    const auto [last, first] = sent_.try_emplace(instance, *at);
    if (first) return true;
    if (last->second == *at) return false;
    last->second = *at;
    return true;
  }

 private:
  std::map<std::string, double> sent_;  // by instance: the time of the last sample sent
};

}  // namespace sanet::sim
