// The laser's keys in a scenario: a fan (fov and beams) or a list of beam directions, on top of
// the laser there (the model's default or already changed).
#include "scenario/sensor_fields.h"
#include "sensors/range_fan.h"
#include "sensors/range_fan_fields.h"

namespace sanet::scenario {
namespace {

struct LaserSettings {
  double fov = 0;
  int beams = 0;
  std::vector<double> angles;  // given instead of fov and beams: the beams' directions, right to left
  double max_range = 0, height = 0, mount_x = 0, noise = 0;
  double direction = 0;  // rad: where the fan or the angles point
};

// A fan's fov and beam count when its directions are exactly those of such a fan; its
// directions otherwise.
LaserSettings PrintedSettings(const sensors::RangeFan& laser) {
  LaserSettings s{0, 0, {}, laser.max_range, laser.mount_height, laser.mount_x, laser.noise, laser.direction};
  const int beams = static_cast<int>(laser.angles.size());
  const double fov = beams > 1 ? laser.angles.back() - laser.angles.front() : kPi;
  if (beams > 0 && sensors::RangeFan::Fan(fov, beams, 0, 0, 1).angles == laser.angles)
    s.fov = fov, s.beams = beams;
  else
    s.angles = laser.angles;
  return s;
}

const Fields<LaserSettings>& LaserFields() {
  static const Fields<LaserSettings> fields = [] {
    Fields<LaserSettings> f;
    f.Custom(
        {"fov", "number", "rad", "`π`", "(0, 2π]", "spread of the fan"},
        [](const Field& v, LaserSettings& s) { s.fov = v.NumberAbove(0, 2 * kPi); },
        [](const LaserSettings& s) { return s.angles.empty() ? NumberNode(s.fov) : YAML::Node(); });
    f.Custom(
        {"beams", "whole number", "", "`181`", "[1, 10000]", "evenly spread from −fov/2 to +fov/2"},
        [](const Field& v, LaserSettings& s) { s.beams = v.Integer(1, 10000); },
        [](const LaserSettings& s) { return s.angles.empty() ? YAML::Node(s.beams) : YAML::Node(); });
    f.Custom(
        {"angles", "list of numbers", "rad", "none", "each in [−2π, 2π]; not with `fov` or `beams`",
         "instead of a fan: each beam's direction, right to left"},
        [](const Field& v, LaserSettings& s) { s.angles = sensors::ReadAngles(v); },
        [](const LaserSettings& s) { return s.angles.empty() ? YAML::Node() : sensors::AngleList(s.angles); });
    f.Number("max_range", Member(&LaserSettings::max_range), "m", 0, 1000, "", true);
    f.Number("height", Member(&LaserSettings::height), "m", 0, 10, "above the ground");
    f.Custom(
        {"mount_x", "number", "m",
         "the front of the body: `body_length / 2 − caster_offset / 4 + 0.01` (0.18) on diffdrive, "
         "`body_radius` on omni3",
         "[−10, 10]", "where the beams start, ahead of the reference point"},
        [](const Field& v, LaserSettings& s) { s.mount_x = v.Number(-10, 10); },
        [](const LaserSettings& s) { return NumberNode(s.mount_x); });
    f.Number("noise", Member(&LaserSettings::noise), "m", 0, 100, "standard deviation of each range");
    // Printed only when turned, so that the effective copy of a forward laser stays as it was.
    f.Custom(
        {"direction", "number", "rad", "`0`", "[−2π, 2π]",
         "where the laser points, robot frame (π: backwards); `fov` and `angles` are around it"},
        [](const Field& v, LaserSettings& s) { s.direction = v.Number(-2 * kPi, 2 * kPi); },
        [](const LaserSettings& s) { return s.direction != 0 ? NumberNode(s.direction) : YAML::Node(); });
    return f;
  }();
  return fields;
}

class LaserKeys : public SensorFields {
 public:
  void Read(const Field& field, std::any& settings) const override {
    if (field.IsMap() && field.Get("angles") && (field.Get("fov") || field.Get("beams")))
      field.Get("angles")->Fail("give either fov and beams (a fan) or angles, not both");
    // A mapping changes the keys it names on the fan there.
    const auto& base = std::any_cast<const sensors::RangeFan&>(settings);
    LaserSettings s{base.angles.back() - base.angles.front(),
                    static_cast<int>(base.angles.size()),
                    {},
                    base.max_range,
                    base.mount_height,
                    base.mount_x,
                    base.noise,
                    base.direction};
    LaserFields().Read(field, s, kInstanceKeys);
    sensors::RangeFan laser = sensors::RangeFan::Fan(s.fov, s.beams, s.mount_x, s.height, s.max_range);
    if (!s.angles.empty()) laser.angles = s.angles;
    laser.noise = s.noise;
    laser.direction = s.direction;
    settings = laser;
  }
  YAML::Node Print(const std::any& settings) const override {
    return LaserFields().Print(PrintedSettings(std::any_cast<const sensors::RangeFan&>(settings)));
  }
  std::vector<FieldInfo> Describe(const std::any& settings) const override {
    return LaserFields().Describe(PrintedSettings(std::any_cast<const sensors::RangeFan&>(settings)));
  }
  bool PrintsAbsence() const override { return true; }
};

}  // namespace

const SensorFields& LaserSensorFields() {
  static const LaserKeys keys;
  return keys;
}

}  // namespace sanet::scenario
