// The encoders' keys in a scenario.
#include "scenario/sensor_fields.h"
#include "sensors/encoders/encoders.h"

namespace sanet::scenario {
namespace {

using sensors::EncodersSettings;

const Fields<EncodersSettings>& EncodersFields() {
  static const Fields<EncodersSettings> fields = [] {
    Fields<EncodersSettings> f;
    f.Number("rate", Member(&EncodersSettings::rate), "Hz", 0, 10000, "samples a second, on the simulated clock", true);
    f.Number("resolution", Member(&EncodersSettings::resolution), "rad", 0, 1,
             "one tick: angles are whole ticks (2π / ticks per turn); 0: exact");
    f.Number("noise", Member(&EncodersSettings::noise), "rad/s", 0, 100, "standard deviation of each speed");
    return f;
  }();
  return fields;
}

}  // namespace

const SensorFields& EncodersSensorFields() {
  static const DeclaredKeys<EncodersSettings> keys(EncodersFields());
  return keys;
}

}  // namespace sanet::scenario
