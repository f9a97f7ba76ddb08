#include "sim/node_batteries.h"

#include <ns3/node-list.h>

#include <algorithm>

namespace sanet::sim {
namespace {

nlohmann::ordered_json TimeOrNull(const std::optional<double>& t) { return t ? nlohmann::ordered_json(*t) : nullptr; }

}  // namespace

void NodeBatteries::Add(NodeId id, const std::optional<energy::EnergySpec>& spec, energy::NodeEnergy::Radios radios,
                        double sensors_w, energy::NodeEnergy::Hooks hooks) {
  energies_.resize(id + 1);
  died_.resize(id + 1);
  first_died_.resize(id + 1);
  if (!spec) return;
  ns3::Ptr<ns3::Node> node = ns3::NodeList::GetNode(id);
  energies_[id] = std::make_unique<energy::NodeEnergy>(*spec, node, radios, sensors_w, std::move(hooks));
  ++count_;
}

std::vector<EnergyLevel> NodeBatteries::Levels() const {
  std::vector<EnergyLevel> levels;
  levels.reserve(count_);
  for (NodeId id = 0; id < energies_.size(); ++id)
    if (energies_[id]) levels.push_back({id, energies_[id]->Reading()});
  return levels;
}

nlohmann::ordered_json NodeBatteries::Summary(const RunNodes& nodes) const {
  nlohmann::ordered_json per_node = nlohmann::ordered_json::object();
  for (NodeId id = 0; id < energies_.size(); ++id) {
    if (!energies_[id]) continue;
    const energy::NodeEnergy& e = *energies_[id];
    nlohmann::ordered_json used = nlohmann::ordered_json::object();
    double total = 0;
    for (const auto& [component, joules] : e.Used()) used[component] = joules, total += joules;
    used["total"] = total;
    nlohmann::ordered_json radio_s = nlohmann::ordered_json::object();
    for (const auto& [state, seconds] : e.RadioSeconds()) radio_s[state] = seconds;
    per_node[nodes.NameOf(id)] = {
        {"battery_j", e.spec().battery_j}, {"remaining_j", e.remaining_j()}, {"used_j", used}, {"radio_s", radio_s},
        {"charged_j", e.charged_j()},      {"died_s", TimeOrNull(died_[id])}};
  }
  return {{"nodes", per_node}, {"lifetime", Lifetime()}};
}

// The sensor network's: the motes with energy (a robot that charges them is not one of them), or
// every node with energy where none is a mote. From first deaths: a revival does not undo one.
nlohmann::ordered_json NodeBatteries::Lifetime() const {
  bool any_mote = false;
  for (const auto& e : energies_) any_mote = any_mote || (e && !e->spec().drive);
  std::vector<double> deaths;
  std::size_t counted = 0, dead = 0;
  for (NodeId id = 0; id < energies_.size(); ++id) {
    if (!energies_[id] || (any_mote && energies_[id]->spec().drive)) continue;
    ++counted;
    if (first_died_[id]) deaths.push_back(*first_died_[id]);
    if (died_[id]) ++dead;
  }
  std::sort(deaths.begin(), deaths.end());
  const auto kth = [&](std::size_t k) -> std::optional<double> {
    return k >= 1 && k <= deaths.size() ? std::optional<double>(deaths[k - 1]) : std::nullopt;
  };
  return {{"nodes", counted},
          {"dead", dead},
          {"first_death_s", TimeOrNull(kth(1))},
          {"half_dead_s", TimeOrNull(kth((counted + 1) / 2))},
          {"last_alive_s", TimeOrNull(kth(counted))}};
}

}  // namespace sanet::sim
