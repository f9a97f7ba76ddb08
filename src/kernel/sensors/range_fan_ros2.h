// What the laser's and the IR ring's ROS 2 messages share (sensors/laser, sensors/ir).
#pragma once

#include <limits>

namespace sanet::ros2_presentation {

// REP 117: a beam that returns nothing within the sensor's range reads +Inf, not its maximum
// (which a consumer would take for an obstacle there). sanet's sensors read their maximum when
// nothing is nearer, and noise is clamped to it, so a reading at the maximum is "nothing seen".
inline float NothingSeenAsInfinity(double range, double max_range) {
  return range >= max_range ? std::numeric_limits<float>::infinity() : static_cast<float>(range);
}

}  // namespace sanet::ros2_presentation
