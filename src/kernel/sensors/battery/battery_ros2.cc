// The battery as sensor_msgs/BatteryState on /<node>/battery_state (or /<node>/<instance>), in
// the node's base_link: charge and capacity in Ah from joules at the battery's voltage, the
// current negative while discharging, the temperature unmeasured (NaN).
#include <cmath>
#include <limits>

#include "ros2_presentation/sensor_messages.h"
#include "sensors/battery/battery.h"

namespace sanet::ros2_presentation {
namespace {

using msg::sensor_msgs::BatteryState;

std::uint8_t StatusOf(const BatteryReading& b) {
  if (b.charging) return BatteryState::POWER_SUPPLY_STATUS_CHARGING;
  if (b.fraction >= 1) return BatteryState::POWER_SUPPLY_STATUS_FULL;
  return b.power_w > 0 ? BatteryState::POWER_SUPPLY_STATUS_DISCHARGING : BatteryState::POWER_SUPPLY_STATUS_NOT_CHARGING;
}

class BatteryMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& instance, const std::any& /*settings*/) const override {
    return {TopicFor<BatteryState>(TopicName(instance, "battery", "battery_state"))};
  }
  std::vector<SensorMessage> Messages(const std::string& /*instance*/, const std::any& /*settings*/,
                                      const SensorReading& reading, const MessageContext& context) const override {
    const auto& b = std::get<BatteryReading>(reading);
    const double amp_hours_per_joule = b.voltage > 0 ? 1 / (b.voltage * 3600) : 0;
    BatteryState s;
    s.header.stamp = StampOf(context.time);
    s.header.frame_id = context.frames->base;
    s.voltage = static_cast<float>(b.voltage);
    s.temperature = std::numeric_limits<float>::quiet_NaN();
    s.current = static_cast<float>(b.voltage > 0 ? -b.power_w / b.voltage : 0);
    s.charge = static_cast<float>(b.remaining_j * amp_hours_per_joule);
    s.capacity = s.design_capacity = static_cast<float>(b.capacity_j * amp_hours_per_joule);
    s.percentage = static_cast<float>(b.fraction);
    s.power_supply_status = StatusOf(b);
    s.power_supply_health = BatteryState::POWER_SUPPLY_HEALTH_GOOD;
    s.power_supply_technology = BatteryState::POWER_SUPPLY_TECHNOLOGY_UNKNOWN;
    s.present = true;
    return {MessageOn(0, s)};
  }
};

}  // namespace

const SensorMessages& BatterySensorMessages() {
  static const BatteryMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
