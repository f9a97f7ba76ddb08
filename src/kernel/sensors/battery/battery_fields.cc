// The battery sensor's keys in a scenario: none; it reads the node's `energy` battery.
#include "scenario/sensor_fields.h"
#include "sensors/battery/battery.h"

namespace sanet::scenario {

const SensorFields& BatterySensorFields() {
  static const Fields<sensors::BatterySettings> fields;
  static const DeclaredKeys<sensors::BatterySettings> keys(fields);
  return keys;
}

}  // namespace sanet::scenario
