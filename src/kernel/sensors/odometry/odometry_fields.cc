// Odometry's keys in a scenario.
#include "scenario/sensor_fields.h"
#include "sensors/odometry/odometry.h"

namespace sanet::scenario {
namespace {

using sensors::OdometrySettings;

const Fields<OdometrySettings>& OdometryFields() {
  static const Fields<OdometrySettings> fields = [] {
    Fields<OdometrySettings> f;
    f.Number("noise", Member(&OdometrySettings::noise), "relative", 0, 10,
             "standard deviation of each increment's relative error");
    return f;
  }();
  return fields;
}

}  // namespace

const SensorFields& OdometrySensorFields() {
  static const DeclaredKeys<OdometrySettings> keys(OdometryFields());
  return keys;
}

}  // namespace sanet::scenario
