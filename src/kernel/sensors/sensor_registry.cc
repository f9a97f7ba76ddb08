#include "sensors/sensor_registry.h"

#include <algorithm>

namespace sanet::sensors {

const std::vector<const SensorKind*>& AllKinds() {
#define SANET_LIST_SENSOR_KIND(name, Name) &Name##Kind(),
  static const std::vector<const SensorKind*> kinds = {SANET_SENSOR_KINDS(SANET_LIST_SENSOR_KIND)};
#undef SANET_LIST_SENSOR_KIND
  return kinds;
}

const SensorKind* FindKind(const std::string& name) {
  for (const SensorKind* kind : AllKinds())
    if (kind->Info().name == name) return kind;
  return nullptr;
}

std::string KindNames() {
  std::string names;
  for (const SensorKind* kind : AllKinds()) names += (names.empty() ? "" : ", ") + kind->Info().name;
  return names;
}

std::size_t KindOrder(const std::string& name) {
  const auto& kinds = AllKinds();
  for (std::size_t i = 0; i < kinds.size(); ++i)
    if (kinds[i]->Info().name == name) return i;
  return kinds.size();
}

robots::SensorConfigs DefaultSensors(const robots::ModelSpec& model) {
  robots::SensorConfigs sensors;
  for (const std::string& name : robots::DefaultSensorKinds(model))
    sensors[name] = {name, FindKind(name)->DefaultSettings(model)};
  return sensors;
}

robots::ModelSpec DefaultModel(robots::ModelKind kind) {
  robots::ModelSpec model = robots::ModelSpec::Defaults(kind);
  model.sensors = DefaultSensors(model);
  return model;
}

std::vector<std::pair<std::string, const robots::SensorConfig*>> OrderedSensors(const robots::ModelSpec& model) {
  std::vector<std::pair<std::string, const robots::SensorConfig*>> out;
  for (const auto& [name, config] : model.sensors) out.emplace_back(name, &config);
  const auto key = [](const std::pair<std::string, const robots::SensorConfig*>& e) {
    return std::make_tuple(KindOrder(e.second->kind), e.first != e.second->kind, e.first);
  };
  std::sort(out.begin(), out.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
  return out;
}

std::vector<std::pair<std::string, const robots::SensorConfig*>> PresentationOrder(const robots::ModelSpec& model) {
  static const std::vector<std::string> kFirst = {"ground_truth", "odometry", "laser", "ir"};
  auto instances = OrderedSensors(model);
  const auto rank = [](const std::string& kind) {
    const auto at = std::find(kFirst.begin(), kFirst.end(), kind);
    return at != kFirst.end() ? static_cast<std::size_t>(at - kFirst.begin()) : kFirst.size() + KindOrder(kind);
  };
  std::stable_sort(instances.begin(), instances.end(),
                   [&](const auto& a, const auto& b) { return rank(a.second->kind) < rank(b.second->kind); });
  return instances;
}

}  // namespace sanet::sensors
