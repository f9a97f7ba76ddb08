// The IR ring's keys in a scenario: on top of the ring there (the model's default or already
// changed), which keeps its mount.
#include "scenario/sensor_fields.h"
#include "sensors/range_fan.h"
#include "sensors/range_fan_fields.h"

namespace sanet::scenario {
namespace {

struct IrSettings {
  std::vector<double> angles;  // rad
  double max_range = 0, height = 0, noise = 0;
};

IrSettings SettingsOf(const sensors::RangeFan& ir) { return {ir.angles, ir.max_range, ir.mount_height, ir.noise}; }

const Fields<IrSettings>& IrFields() {
  static const Fields<IrSettings> fields = [] {
    Fields<IrSettings> f;
    f.Custom(
        {"count", "whole number", "", "`6`", "[1, 360]", "sensors evenly spaced, sensor 0 forward"},
        [](const Field& v, IrSettings& s) { s.angles = sensors::RangeFan::Ring(v.Integer(1, 360), 0, 0, 1).angles; },
        [](const IrSettings&) { return YAML::Node(); });
    f.Custom(
        {"angles", "list of numbers", "rad", "evenly spaced", "each in [−2π, 2π]; not with `count`",
         "each sensor's direction"},
        [](const Field& v, IrSettings& s) { s.angles = sensors::ReadAngles(v); },
        [](const IrSettings& s) { return sensors::AngleList(s.angles); });
    f.Number("max_range", Member(&IrSettings::max_range), "m", 0, 100, "", true);
    f.Number("height", Member(&IrSettings::height), "m", 0, 10, "above the ground");
    f.Number("noise", Member(&IrSettings::noise), "m", 0, 100, "standard deviation of each range");
    return f;
  }();
  return fields;
}

class IrKeys : public SensorFields {
 public:
  void Read(const Field& field, std::any& settings) const override {
    if (field.IsMap() && field.Get("count") && field.Get("angles"))
      field.Get("angles")->Fail("give either count (evenly spaced) or angles, not both");
    sensors::RangeFan ir = std::any_cast<sensors::RangeFan>(settings);
    IrSettings keys = SettingsOf(ir);
    IrFields().Read(field, keys, kInstanceKeys);
    ir.angles = keys.angles;
    ir.max_range = keys.max_range;
    ir.mount_height = keys.height;
    ir.noise = keys.noise;
    settings = ir;
  }
  YAML::Node Print(const std::any& settings) const override {
    return IrFields().Print(SettingsOf(std::any_cast<const sensors::RangeFan&>(settings)));
  }
  std::vector<FieldInfo> Describe(const std::any& settings) const override {
    return IrFields().Describe(SettingsOf(std::any_cast<const sensors::RangeFan&>(settings)));
  }
  bool PrintsAbsence() const override { return true; }
};

}  // namespace

const SensorFields& IrSensorFields() {
  static const IrKeys keys;
  return keys;
}

}  // namespace sanet::scenario
