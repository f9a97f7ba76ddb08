#include "sensors/battery/battery.h"

#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class BatteryGauge : public SensorInstance {
 public:
  std::optional<SensorReading> Read(const ReadContext& context) override {
    if (!context.battery) return std::nullopt;
    const std::optional<BatteryReading> reading = context.battery();
    if (!reading) return std::nullopt;
    return *reading;
  }
};

class Battery : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"battery",
                                 "the node's battery: charge left, fraction, voltage, power drawn (needs `energy`)",
                                 "BatteryReading",
                                 "remaining_j and capacity_j in J, fraction in [0, 1], voltage in V, power_w in W",
                                 "sensor_msgs/msg/BatteryState",
                                 "battery_state"};
    return info;
  }
  std::any DefaultSettings(const robots::ModelSpec& /*model*/) const override { return BatterySettings{}; }
  std::unique_ptr<SensorInstance> Create(const std::any& /*settings*/, Mount /*mount*/) const override {
    return std::make_unique<BatteryGauge>();
  }
};

}  // namespace

const SensorKind& BatteryKind() {
  static const Battery kind;
  return kind;
}

}  // namespace sanet::sensors
