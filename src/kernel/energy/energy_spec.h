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
const RadioPreset& RadioPresetNamed(const std::string& name);  // one of RadioPresets()

enum class Chemistry {
  kConstantVoltage,  // sanet's Battery (energy/battery.h)
  kLiIon,            // a voltage curve: ns-3's LiIonEnergySource (energy/li_ion_cell.h)
};

// What a robot's drive draws (docs/energy.md#motion): `idle_w` while the node is on, and the
// motors' positive mechanical work with the rolling resistance's, over `efficiency`.
struct DriveCosts {
  double efficiency = 0.6;           // of the motors, gears and drivers: electrical power to wheel power
  double idle_w = 0.5;               // motor drivers and encoders, moving or not
  double rolling_resistance = 0.01;  // coefficient: the force it takes to roll, per newton of weight
};

// A wireless charger a robot carries for the motes around it (docs/energy.md#chargers): it
// radiates `power_w`, of which a mote at distance d (antenna to antenna, m) receives
// power_w * alpha / (d + beta)^2, at most `power_w`, out to `range_m`.
struct WirelessCharger {
  double power_w = 0;
  double range_m = 0;
  double alpha = 0.0034;  // m^2: Friis at 915 MHz, 8 dBi and 2 dBi antennas, a 50 % rectifier (docs)
  double beta = 0.2316;   // m
  double Efficiency(double d) const { return d > range_m ? 0 : std::min(1.0, alpha / ((d + beta) * (d + beta))); }
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
  RadioCurrents radio;     // its 802.11 radio's (WifiRadioEnergyModel)
  bool wifi_radio = true;  // false where the node's only radio is 802.15.4 (set by the loader): no `radio` then
  // Its 802.15.4 radio's tx, rx, idle and sleep currents (energy/lr_wpan_energy_model.h): set by
  // the loader on nodes with such a radio, the CC2420's unless the scenario says.
  struct NamedCurrents {
    std::string preset;
    RadioCurrents currents;
  };
  std::optional<NamedCurrents> lr_wpan_radio;
  std::optional<DriveCosts> drive;  // a robot's (set by the loader); a mote has none
  std::optional<WirelessCharger> wireless_charger;
};

}  // namespace sanet::energy
