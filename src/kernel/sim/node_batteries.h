// The run's batteries: one energy::NodeEnergy per node that has `energy`, with when each died,
// and the network's lifetime from those deaths (docs/energy.md).
#pragma once

#include <ns3/net-device.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "energy/node_energy.h"
#include "sim/run_events.h"
#include "sim/run_nodes.h"

namespace sanet::sim {

class NodeBatteries {
 public:
  // Node `id` (the next one) with `spec`'s energy, or none; `radio` is its Wi-Fi device or null;
  // `sensors_w` what its sensors draw while it is on.
  void Add(NodeId id, const std::optional<energy::EnergySpec>& spec, energy::NodeEnergy::Radios radios,
           double sensors_w, energy::NodeEnergy::Hooks hooks);
  bool any() const { return count_ > 0; }
  energy::NodeEnergy* Of(NodeId id) const { return id < energies_.size() ? energies_[id].get() : nullptr; }
  std::vector<EnergyLevel> Levels() const;
  // Every robot's battery takes what its drive still owes (NodeEnergy::SettleMotion).
  void SettleMotion() const {
    for (const auto& e : energies_)
      if (e) e->SettleMotion();
  }

  void Died(NodeId id, double t) {
    died_.at(id) = t;
    if (!first_died_.at(id)) first_died_.at(id) = t;
  }
  void Revived(NodeId id) { died_.at(id).reset(); }
  bool dead(NodeId id) const { return died_.at(id).has_value(); }

  // summary.json's `energy`: per node what was used by component, charged and when it died; the
  // network's lifetime from its motes' first deaths (a revival does not undo one; robots count
  // only where there are no motes): the first, half of the nodes' and the last.
  nlohmann::ordered_json Summary(const RunNodes& nodes) const;

 private:
  nlohmann::ordered_json Lifetime() const;

  std::vector<std::unique_ptr<energy::NodeEnergy>> energies_;
  std::vector<std::optional<double>> died_;        // while dead
  std::vector<std::optional<double>> first_died_;  // its first death, revived or not: the lifetime's
  std::size_t count_ = 0;
};

}  // namespace sanet::sim
