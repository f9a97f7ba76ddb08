// What a node's energy is, as a scenario's `energy` key says (docs/energy.md): a battery, the
// electronics' constant draw and the radio's current in each of its states. A node without one
// has an infinite supply.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace sanet::energy {

// The radio's current in each state of ns-3's Wi-Fi PHY (WifiRadioEnergyModel's attributes), A.
struct RadioCurrents {
  double tx_a = 0.38;
  double rx_a = 0.313;
  double idle_a = 0.273;
  std::optional<double> cca_busy_a;  // unset: the idle current
  double switching_a = 0.273;        // changing channel (sanet's radios never do)
  double sleep_a = 0.033;
  double cca_busy() const { return cca_busy_a.value_or(idle_a); }
};

// Named sets of currents, each with where its figures come from (docs/energy.md).
struct RadioPreset {
  std::string name, source;
  RadioCurrents currents;
};
const std::vector<RadioPreset>& RadioPresets();

enum class Chemistry {
  kConstantVoltage,  // sanet's Battery (energy/battery.h)
  kLiIon,            // a voltage curve: ns-3's LiIonEnergySource (energy/li_ion_cell.h)
};

struct EnergySpec {
  Chemistry source = Chemistry::kConstantVoltage;
  double battery_j = 0;          // capacity, J
  double voltage = 3;            // V, constant
  double initial_fraction = 1;   // of the capacity, at the start
  double electronics_w = 0;      // drawn while the node is alive
  double cutoff = 0;             // the node dies when its charge falls to this fraction
  std::optional<double> revive;  // a dead node comes back once recharged above this fraction
  double RevivesAbove() const { return revive.value_or(std::min(1.0, cutoff + 0.05)); }
  std::string radio_preset = "ns3_wifi";
  RadioCurrents radio;
};

}  // namespace sanet::energy
