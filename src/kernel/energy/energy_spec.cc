#include "energy/energy_spec.h"

#include <stdexcept>

namespace sanet::energy {

const std::vector<RadioPreset>& RadioPresets() {
  static const std::vector<RadioPreset> presets = {
      {"ns3_wifi", "ns-3 3.37's WifiRadioEnergyModel defaults (an 802.11 card)", RadioCurrents{}},
      {"cc2420",
       "the TI CC2420 datasheet (SWRS041): transmit at 0 dBm 17.4 mA, receive 18.8 mA, idle 0.426 mA, "
       "power-down 0.02 mA",
       RadioCurrents{0.0174, 0.0188, 0.000426, std::nullopt, 0.000426, 0.00002}},
  };
  return presets;
}

const RadioPreset& RadioPresetNamed(const std::string& name) {
  for (const RadioPreset& p : RadioPresets())
    if (p.name == name) return p;
  throw std::logic_error("no radio preset named " + name);
}

}  // namespace sanet::energy
