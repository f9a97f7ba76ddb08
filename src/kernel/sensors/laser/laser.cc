// The planar laser: a fan of rays from the front of the body.
#include "sensors/range_fan.h"
#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class Laser : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"laser",
                                 "a planar laser scanner: a fan of rays, right to left",
                                 "RangeScan",
                                 "ranges in m, angles in rad",
                                 "sensor_msgs/msg/LaserScan",
                                 "scan"};
    return info;
  }
  // 181 beams over 180 degrees, 8 m, from the front of the body 20 cm up.
  std::any DefaultSettings(const robots::ModelSpec& model) const override {
    return RangeFan::Fan(kPi, 181, robots::FrontX(model), 0.2, 8.0);
  }
  std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const override {
    return std::make_unique<RangeFanSensor>(std::any_cast<const RangeFan&>(settings), mount);
  }
};

}  // namespace

const SensorKind& LaserKind() {
  static const Laser kind;
  return kind;
}

}  // namespace sanet::sensors
