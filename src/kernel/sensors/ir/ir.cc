// The IR ring: short rays around the body, low enough to see motes.
#include "sensors/range_fan.h"
#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class Ir : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"ir",
                                 "a ring of infrared range sensors, one ray each",
                                 "RangeScan",
                                 "ranges in m, angles in rad",
                                 "sensor_msgs/msg/Range (one topic per sensor)",
                                 "ir_<i>"};
    return info;
  }
  // Six sensors at the body's edge, 6 cm up, 0.8 m range.
  std::any DefaultSettings(const robots::ModelSpec& model) const override {
    return RangeFan::Ring(6, robots::EdgeRadius(model), 0.06, 0.8);
  }
  std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const override {
    return std::make_unique<RangeFanSensor>(std::any_cast<const RangeFan&>(settings), mount);
  }
};

}  // namespace

const SensorKind& IrKind() {
  static const Ir kind;
  return kind;
}

}  // namespace sanet::sensors
