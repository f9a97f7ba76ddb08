#include "scenario/sensor_fields.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <stdexcept>

#include "ros2_presentation/sensor_messages.h"
#include "sensors/sensor_registry.h"

namespace sanet::scenario {
namespace {

const SensorFields& FieldsOf(const std::string& kind) {
#define SANET_FIELDS_IF(name, Name) \
  if (kind == #name) return Name##SensorFields();
  SANET_SENSOR_KINDS(SANET_FIELDS_IF)
#undef SANET_FIELDS_IF
  throw std::logic_error("sensor kind " + kind + " has no scenario fields");
}

// The kind of the instance `name`: its `kind` key, or its own name (a kind's default instance).
const sensors::SensorKind& KindOf(const std::string& name, const Field& value) {
  const sensors::SensorKind* own = sensors::FindKind(name);
  const std::optional<Field> key = value.IsMap() ? value.Get("kind") : std::nullopt;
  if (!key) {
    if (!own)
      value.Fail("unknown sensor '" + name + "': a sensor is a kind's name (" + sensors::KindNames() +
                 ") or another name with `kind:`");
    return *own;
  }
  const std::string kind = key->Text();
  const sensors::SensorKind* named = sensors::FindKind(kind);
  if (!named) key->Fail("unknown sensor kind '" + kind + "' (known: " + sensors::KindNames() + ")");
  if (own && own != named)
    key->Fail("'" + name + "' is the " + name + " sensor's own name: give this " + kind + " another name");
  return *named;
}

// "noise_position, noise_angle": the kind's keys (those without a default only, if `required`).
std::string KeysOf(const sensors::SensorKind& kind, const robots::ModelSpec& model, bool required) {
  std::string keys;
  for (const FieldInfo& f : FieldsOf(kind.Info().name).Describe(kind.DefaultSettings(model)))
    if (!required || f.default_text == kRequired) keys += (keys.empty() ? "" : ", ") + f.key;
  return keys;
}

// A lower-case letter, then letters, digits and _: the name is part of the sensor's topics and
// frames, and the lower-case start keeps it apart from USARSim's sensor names on SEN lines
// (Scanner1, IR0, GroundTruth).
bool IsToken(const std::string& name) {
  if (name.empty() || !std::islower(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// power_w and energy_j, printed only where set (a sensor that costs nothing says nothing).
const Fields<robots::SensorConfig>& DrawFields() {
  static const Fields<robots::SensorConfig> fields = [] {
    Fields<robots::SensorConfig> f;
    const auto printed = [](double robots::SensorConfig::*member) {
      return [member](const robots::SensorConfig& c) { return c.*member > 0 ? NumberNode(c.*member) : YAML::Node(); };
    };
    f.Custom(
        {"power_w", "number", "W", "`0`", "[0, 1e6]",
         "drawn from the node's battery while the node is on (with `energy`; docs/energy.md#sensors)"},
        [](const Field& v, robots::SensorConfig& c) { c.power_w = v.Number(0, 1e6); },
        printed(&robots::SensorConfig::power_w));
    f.Custom(
        {"energy_j", "number", "J", "`0`", "[0, 1e6]",
         "drawn from the node's battery at each reading its controller (or robot client) takes"},
        [](const Field& v, robots::SensorConfig& c) { c.energy_j = v.Number(0, 1e6); },
        printed(&robots::SensorConfig::energy_j));
    return f;
  }();
  return fields;
}

// `link: NAME` on a robot from a URDF: the sensor's mount (mount_x, and mount_y and height where
// the kind has them) is the link's place (keys the sensor gives itself are read after). Read as
// the kind's own keys, so that they print as those.
void MountOnLink(const Field& link, const Field& value, const robots::ModelSpec& model, const std::string& kind,
                 std::any& settings) {
  std::vector<std::string> keys;  // of the mount, that the kind has
  for (const FieldInfo& key : FieldsOf(kind).Describe(settings))
    if (key.key == "mount_x" || key.key == "mount_y" || key.key == "mount_z" || key.key == "height")
      keys.push_back(key.key);
  if (std::find(keys.begin(), keys.end(), "mount_x") == keys.end())
    link.Fail("a sensor of kind " + kind + " has no mount (mount_x) to put on a link: it takes no `link`");
  if (!model.urdf) link.Fail("names a URDF link: the robot's body needs `urdf`");
  const auto place = model.urdf->links.find(link.Text());
  if (place == model.urdf->links.end()) {
    std::string links;
    for (const auto& [name, pose] : model.urdf->links) links += (links.empty() ? "" : ", ") + name;
    link.Fail("the robot's URDF has no link '" + link.Text() + "' (its links: " + links + ")");
  }
  YAML::Node mount(YAML::NodeType::Map);
  for (const std::string& key : keys) mount[key] = place->second[key == "mount_x" ? 0 : key == "mount_y" ? 1 : 2];
  FieldsOf(kind).Read(Field(mount, value.path(), std::make_shared<const std::string>(value.file())), settings);
}

void ReadInstance(const std::string& name, const Field& value, robots::ModelSpec& model) {
  if (!IsToken(name))
    value.Fail(
        "a sensor's name is letters, digits and _, starting with a lower-case letter: it names its ROS 2 "
        "topics and frames");
  const sensors::SensorKind& kind = KindOf(name, value);
  const std::string& kind_name = kind.Info().name;
  if (const auto why = kind.Refuses(model)) value.Fail(*why);
  if (value.IsScalar() && !value.Bool()) {
    if (!kind.Removable())
      value.Fail("every node has its " + name + ", which cannot be taken off; its keys are " +
                 KeysOf(kind, model, false));
    model.sensors.erase(name);
    return;
  }
  const auto it = model.sensors.find(name);
  robots::SensorConfig config{kind_name, kind.DefaultSettings(model)};
  std::any& settings = config.settings;
  if (value.IsScalar()) {  // true: the kind's default instance
    if (FieldsOf(kind_name).NeedsKeys())
      value.Fail("a " + kind_name + " sensor needs " + KeysOf(kind, model, true) + ": give {" +
                 KeysOf(kind, model, true) + ": ...} instead of true");
  } else {
    if (it != model.sensors.end() && it->second.kind == kind_name) config = it->second;
    if (auto link = value.Get("link")) MountOnLink(*link, value, model, kind_name, settings);
    FieldsOf(kind_name).Read(value, settings);  // after: mount_x and height given override the link's
    DrawFields().ReadPresent(value, config);
  }
  model.sensors[name] = std::move(config);
}

// No two instances publish on one topic (`scan: {kind: sonar}` beside the laser's /R/scan).
void CheckTopics(const Field& field, const robots::ModelSpec& model) {
  std::map<std::string, std::string> publisher;  // topic -> instance
  for (const auto& [instance, config] : sensors::PresentationOrder(model)) {
    const ros2_presentation::SensorMessages* kind = ros2_presentation::MessagesOf(config->kind);
    if (!kind) continue;
    for (const ros2_presentation::SensorTopic& topic : kind->Topics(instance, config->settings)) {
      const auto [other, fresh] = publisher.emplace(topic.name, instance);
      if (fresh) continue;
      const std::string named = instance == config->kind ? other->second : instance;
      const std::optional<Field> at = field.Get(named);
      (at ? *at : field)
          .Fail("sensors '" + other->second + "' and '" + instance + "' would both publish /<robot>/" + topic.name +
                ": give '" + named + "' another name");
    }
  }
}

// The instance as the effective scenario prints it: a named one starts with its kind.
YAML::Node PrintInstance(const std::string& name, const robots::SensorConfig& config) {
  YAML::Node keys = FieldsOf(config.kind).Print(config.settings);
  for (const auto& entry : DrawFields().Print(config)) keys[entry.first.Scalar()] = entry.second;
  if (name == config.kind) return keys;
  YAML::Node out(YAML::NodeType::Map);
  out["kind"] = config.kind;
  for (const auto& entry : keys) out[entry.first.Scalar()] = entry.second;
  return out;
}

}  // namespace

void ReadSensors(const Field& field, robots::ModelSpec& model) {
  if (!field.IsMap())
    field.Fail("expected a mapping of sensors by name (" + sensors::KindNames() + ", or a name with `kind:`)");
  std::vector<std::string> names;
  for (const auto& entry : field.node()) names.push_back(entry.first.Scalar());
  field.ExpectKeys(names);  // each name once
  for (const std::string& name : names) ReadInstance(name, *field.Get(name), model);
  CheckTopics(field, model);
}

YAML::Node PrintSensors(const robots::ModelSpec& model) {
  YAML::Node out(YAML::NodeType::Map);
  const std::vector<std::string> carried = robots::DefaultSensorKinds(model);
  const auto instances = sensors::OrderedSensors(model);
  for (const sensors::SensorKind* kind : sensors::AllKinds()) {
    const std::string& name = kind->Info().name;
    const auto own = model.sensors.find(name);
    const bool has_own = own != model.sensors.end() && own->second.kind == name;
    const bool is_carried = std::find(carried.begin(), carried.end(), name) != carried.end();
    if (!has_own && (FieldsOf(name).PrintsAbsence() || is_carried)) out[name] = false;
    for (const auto& [instance, config] : instances)
      if (config->kind == name) out[instance] = PrintInstance(instance, *config);
  }
  return out;
}

std::vector<std::pair<std::string, std::vector<FieldInfo>>> SensorTables() {
  std::vector<std::pair<std::string, std::vector<FieldInfo>>> tables;
  for (const sensors::SensorKind* kind : sensors::AllKinds()) {
    const std::string& name = kind->Info().name;
    // The defaults of the first model that carries the kind (any model's, if none does).
    robots::ModelSpec example = robots::ModelSpec::Defaults(robots::AllModels().front());
    for (robots::ModelKind model : robots::AllModels()) {
      const auto carried = robots::DefaultSensorKinds(robots::ModelSpec::Defaults(model));
      if (std::find(carried.begin(), carried.end(), name) != carried.end()) {
        example = robots::ModelSpec::Defaults(model);
        break;
      }
    }
    std::vector<FieldInfo> keys = FieldsOf(name).Describe(kind->DefaultSettings(example));
    for (FieldInfo& draw : DrawFields().Describe(robots::SensorConfig{})) keys.push_back(std::move(draw));
    tables.push_back({"sensors." + name, std::move(keys)});
  }
  return tables;
}

}  // namespace sanet::scenario
