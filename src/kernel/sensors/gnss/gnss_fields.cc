// The satellite fix's keys in a scenario.
#include "scenario/sensor_fields.h"
#include "sensors/gnss/gnss.h"

namespace sanet::scenario {
namespace {

using sensors::GnssSettings;

const Fields<GnssSettings>& GnssFields() {
  static const Fields<GnssSettings> fields = [] {
    Fields<GnssSettings> f;
    f.Number("rate", Member(&GnssSettings::rate), "Hz", 0, 1000, "fixes a second, on the simulated clock", true);
    f.Number("mount_x", Member(&GnssSettings::mount_x), "m", -10, 10, "the antenna ahead of the reference point");
    f.Number("mount_y", Member(&GnssSettings::mount_y), "m", -10, 10, "the antenna left of the reference point");
    f.Number("height", Member(&GnssSettings::height), "m", 0, 100, "the antenna above the ground");
    f.Number("horizontal_noise", Member(&GnssSettings::horizontal_noise), "m", 0, 1000,
             "standard deviation of the error east and north");
    f.Number("vertical_noise", Member(&GnssSettings::vertical_noise), "m", 0, 1000,
             "standard deviation of the error up");
    f.Number("correlation_time", Member(&GnssSettings::correlation_time), "s", 0, 1e6,
             "of the error's wander (first-order Gauss-Markov); `0`: white");
    return f;
  }();
  return fields;
}

}  // namespace

const SensorFields& GnssSensorFields() {
  static const DeclaredKeys<GnssSettings> keys(GnssFields());
  return keys;
}

}  // namespace sanet::scenario
