// The registered sensor kinds (sensors/sensor_kinds.h), for the kernel: found by name, listed in
// order, and a model's default sensors.
#pragma once

#include <string>
#include <vector>

#include "robots/node_model.h"
#include "sensors/sensor_kind.h"
#include "sensors/sensor_kinds.h"

namespace sanet::sensors {

#define SANET_DECLARE_SENSOR_KIND(name, Name) const SensorKind& Name##Kind();
SANET_SENSOR_KINDS(SANET_DECLARE_SENSOR_KIND)
#undef SANET_DECLARE_SENSOR_KIND

const std::vector<const SensorKind*>& AllKinds();
const SensorKind* FindKind(const std::string& name);  // null for an unknown kind
std::string KindNames();                              // "ir, laser, ..." for error messages
// A kind's place in AllKinds(): the order instances are listed and read in.
std::size_t KindOrder(const std::string& name);

// The sensors `model` carries by default, placed on its body as it is.
robots::SensorConfigs DefaultSensors(const robots::ModelSpec& model);
// A model with its body defaults and the sensors it carries by default (robots::DefaultSensorKinds).
robots::ModelSpec DefaultModel(robots::ModelKind kind);
// The model's instances in the order they are listed and read: by kind, then the default
// instance before named ones, then by name.
std::vector<std::pair<std::string, const robots::SensorConfig*>> OrderedSensors(const robots::ModelSpec& model);
// The instances in the order front ends present them (SEN lines, ROS 2 topics and their ids in the
// MCAP log, the driver's reads): ground truth, odometry, laser, IR, as before kinds were
// registered, then the other kinds in registry order; within a kind as OrderedSensors.
std::vector<std::pair<std::string, const robots::SensorConfig*>> PresentationOrder(const robots::ModelSpec& model);
// An instance's settings when it is of `kind`; null otherwise (no such instance, another kind).
template <typename T>
const T* SettingsOf(const robots::ModelSpec& model, const std::string& instance, const std::string& kind) {
  const auto it = model.sensors.find(instance);
  if (it == model.sensors.end() || it->second.kind != kind) return nullptr;
  return std::any_cast<T>(&it->second.settings);
}

}  // namespace sanet::sensors
