// The sonar's keys in a scenario.
#include "scenario/sensor_fields.h"
#include "sensors/sonar/sonar.h"

namespace sanet::scenario {
namespace {

using sensors::SonarSettings;

const Fields<SonarSettings>& SonarFields() {
  static const Fields<SonarSettings> fields = [] {
    Fields<SonarSettings> f;
    f.Custom(
        {"direction", "number", "rad", "`0`", "[−2π, 2π]",
         "where the cone points, robot frame (0 ahead, positive left)"},
        [](const Field& v, SonarSettings& s) { s.direction = v.Number(-2 * kPi, 2 * kPi); },
        [](const SonarSettings& s) { return NumberNode(s.direction); });
    f.Custom(
        {"fov", "number", "rad", "`0.5`", "[0, π]", "the cone's full width"},
        [](const Field& v, SonarSettings& s) { s.fov = v.Number(0, kPi); },
        [](const SonarSettings& s) { return NumberNode(s.fov); });
    f.Whole<int>("rays", Member(&SonarSettings::rays), "", 1, 1000, "rays sampling the cone");
    f.Number("max_range", Member(&SonarSettings::max_range), "m", 0, 100, "", true);
    f.Number("height", Member(&SonarSettings::height), "m", 0, 10, "above the ground");
    f.Custom(
        {"mount_radius", "number", "m",
         "the model's edge radius: `body_radius` on omni3, `body_width / 2` on diffdrive (whatever the direction)",
         "[0, 10]", "how far out from the reference point, along `direction`, the cone starts"},
        [](const Field& v, SonarSettings& s) { s.mount_radius = v.Number(0, 10); },
        [](const SonarSettings& s) { return NumberNode(s.mount_radius); });
    f.Number("noise", Member(&SonarSettings::noise), "m", 0, 100, "standard deviation of the range");
    return f;
  }();
  return fields;
}

}  // namespace

const SensorFields& SonarSensorFields() {
  static const DeclaredKeys<SonarSettings> keys(SonarFields());
  return keys;
}

}  // namespace sanet::scenario
