// The bearing sensor's keys in a scenario: its range has no default.
#include "scenario/sensor_fields.h"
#include "sensors/bearing/bearing.h"

namespace sanet::scenario {
namespace {

using sensors::BearingSettings;

const Fields<BearingSettings>& BearingFields() {
  static const Fields<BearingSettings> fields = [] {
    Fields<BearingSettings> f;
    f.Custom(
        {"range", "number", "m", "required", "(0, 1e6]", "beyond it the sensor answers nothing"},
        [](const Field& v, BearingSettings& s) { s.range = v.NumberAbove(0, 1e6); },
        [](const BearingSettings& s) { return NumberNode(s.range); });
    f.Number("noise_distance", Member(&BearingSettings::noise_distance), "m", 0, 1000, "standard deviation");
    f.Number("noise_angle", Member(&BearingSettings::noise_angle), "rad", 0, 10, "standard deviation");
    return f;
  }();
  return fields;
}

}  // namespace

const SensorFields& BearingSensorFields() {
  static const DeclaredKeys<BearingSettings> keys(BearingFields(), /*needs_keys=*/true);
  return keys;
}

}  // namespace sanet::scenario
