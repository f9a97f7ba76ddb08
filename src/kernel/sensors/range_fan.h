// A fan of rays cast from a mount on the body, the shared physics of the IR ring (sensors/ir)
// and the planar laser (sensors/laser): Gaussian noise per range when `noise` is non-zero.
#pragma once

#include <vector>

#include "sensors/sensor_kind.h"
#include "sensors/sensor_registry.h"

namespace sanet::sensors {

struct RangeFan {
  std::vector<double> angles;  // rad, one per beam, from `direction`
  double direction = 0;        // rad, robot frame: where the fan points (0 ahead); a reading's angles include it
  double max_range = 1.0;      // m
  double mount_x = 0;          // m, robot frame, where the rays start (before `mount_radius`)
  double mount_radius = 0;     // m, rays start this far out along their own direction
  double mount_height = 0.1;   // m above the ground
  double noise = 0;            // m, standard deviation of each range

  // `count` rays evenly spaced, ray 0 forward, starting `radius` out.
  static RangeFan Ring(int count, double radius, double height, double max_range);
  // `beams` rays spread over `fov`, right to left as laser scanners report, from `mount_x` ahead.
  static RangeFan Fan(double fov, int beams, double mount_x, double height, double max_range);
};

// The default instance of `kind` ("ir", "laser") on `model`; null without one.
inline const RangeFan* DefaultFan(const robots::ModelSpec& model, const char* kind) {
  return SettingsOf<RangeFan>(model, kind, kind);
}

class RangeFanSensor : public SensorInstance {
 public:
  RangeFanSensor(RangeFan fan, Mount mount) : fan_(std::move(fan)), mount_(mount) {}
  std::optional<SensorReading> Read(const ReadContext& context) override;

 private:
  RangeFan fan_;
  Mount mount_;
};

}  // namespace sanet::sensors
