// A node's `sensors` in a scenario, through the registered kinds (sensors/sensor_kinds.h): each
// kind's folder holds its part here, sensors/<kind>/<kind>_fields.cc, which reads its keys onto an
// instance's settings, prints them back, and describes them for the docs.
//
//   sensors:
//     laser: {max_range: 5}                  # the kind's default instance, changed
//     ir: false                              # taken off
//     bearing: {range: 20}                   # added
//     laser_rear: {kind: laser, fov: 1.5}    # another instance of a kind, by name
#pragma once

#include <any>
#include <string>
#include <utility>
#include <vector>

#include "robots/node_model.h"
#include "scenario/fields.h"
#include "sensors/sensor_kinds.h"

namespace sanet::scenario {

// The keys every sensor instance has, which ReadSensors reads beside the kind's own: its kind,
// and its draw on the node's battery.
inline const std::vector<std::string> kInstanceKeys = {"kind", "power_w", "energy_j", "link"};

class SensorFields {
 public:
  virtual ~SensorFields() = default;
  // Reads the mapping `field` onto `settings` (the instance's, or the kind's default on the
  // node's model); `kind` is the one key it leaves to the caller.
  virtual void Read(const Field& field, std::any& settings) const = 0;
  virtual YAML::Node Print(const std::any& settings) const = 0;
  // The keys for the docs and `sanet list`, with the defaults of `settings`.
  virtual std::vector<FieldInfo> Describe(const std::any& settings) const = 0;
  // Whether the effective scenario says `<kind>: false` on a node without the kind (ir and laser
  // do, as they always have); a kind a model carries by default always does.
  virtual bool PrintsAbsence() const { return false; }
  // Whether the kind has keys without defaults, so that `<kind>: true` is not enough (bearing's
  // range).
  virtual bool NeedsKeys() const { return false; }
};

// The part of a kind whose keys are all declared fields of its settings (most kinds): reads them
// onto the settings, prints and describes them.
template <typename Settings>
class DeclaredKeys : public SensorFields {
 public:
  explicit DeclaredKeys(const Fields<Settings>& fields, bool needs_keys = false)
      : fields_(fields), needs_keys_(needs_keys) {}
  void Read(const Field& field, std::any& settings) const override {
    auto s = std::any_cast<Settings>(settings);
    fields_.Read(field, s, kInstanceKeys);
    settings = s;
  }
  YAML::Node Print(const std::any& settings) const override {
    return fields_.Print(std::any_cast<const Settings&>(settings));
  }
  std::vector<FieldInfo> Describe(const std::any& settings) const override {
    return fields_.Describe(std::any_cast<const Settings&>(settings));
  }
  bool NeedsKeys() const override { return needs_keys_; }

 private:
  const Fields<Settings>& fields_;
  bool needs_keys_;
};

#define SANET_DECLARE_SENSOR_FIELDS(name, Name) const SensorFields& Name##SensorFields();
SANET_SENSOR_KINDS(SANET_DECLARE_SENSOR_FIELDS)
#undef SANET_DECLARE_SENSOR_FIELDS

// Reads a node's `sensors` mapping onto `model`, which holds the sensors its model carries.
void ReadSensors(const Field& field, robots::ModelSpec& model);
// The node's sensors as the effective scenario prints them.
YAML::Node PrintSensors(const robots::ModelSpec& model);
// Per kind, in order: "sensors.<kind>" and its keys with the defaults of a model that carries it.
std::vector<std::pair<std::string, std::vector<FieldInfo>>> SensorTables();

}  // namespace sanet::scenario
