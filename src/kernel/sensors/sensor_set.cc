#include "sensors/sensor_set.h"

#include "sensors/sensor_registry.h"

namespace sanet::sensors {

SensorSet::SensorSet(physics::PhysicsWorld& world, const robots::NodeModel& model, const Pose2D& start,
                     std::uint64_t seed, const std::string& stream_prefix, const Surroundings& surroundings,
                     NodeId self) {
  for (const auto& [name, config] : PresentationOrder(model.spec())) {
    const SensorKind* kind = FindKind(config->kind);
    if (!kind) continue;  // the scenario's reader refused unknown kinds already
    Mount mount{world, model, start, RandomStream(seed, stream_prefix + "/" + name), surroundings, self};
    entries_.push_back({name, config->kind, kind->Create(config->settings, mount)});
    if (auto* sampler = dynamic_cast<SamplingSensor*>(entries_.back().instance.get())) samplers_.push_back(sampler);
    names_.push_back(name);
  }
}

const SensorSet::Entry* SensorSet::Find(const std::string& name) const {
  for (const Entry& e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

std::string SensorSet::KindOf(const std::string& name) const {
  const Entry* e = Find(name);
  return e ? e->kind : "";
}

std::optional<SensorReading> SensorSet::Read(const std::string& name, const ReadContext& context) {
  const Entry* e = Find(name);
  if (!e) return std::nullopt;
  return e->instance->Read(context);
}

std::optional<double> SensorSet::SampledAt(const std::string& name) const {
  const Entry* e = Find(name);
  return e ? e->instance->SampledAt() : std::nullopt;
}

void SensorSet::SampleOwnClocks(double time) {
  for (SamplingSensor* s : samplers_) s->SampleUntil(time);
}

void SensorSet::TakeSamples(std::vector<Sample>& out) {
  if (samplers_.empty()) return;
  for (Entry& e : entries_) {
    taken_.clear();
    e.instance->TakeSamples(taken_);
    for (TimedReading& r : taken_) out.push_back({&e.name, &e.kind, std::move(r)});
  }
}

void SensorSet::AfterPhysicsStep(double time) {
  for (Entry& e : entries_) e.instance->AfterPhysicsStep(time);
}

}  // namespace sanet::sensors
