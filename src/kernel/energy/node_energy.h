// One node's energy on ns-3's energy framework: its battery (energy/battery.h), the electronics'
// draw (energy/electronics_model.h) and, on a node with a Wi-Fi radio, ns-3's
// WifiRadioEnergyModel (energy/radio_energy_model.h) driven by the PHY's real states, with the time in each state
// summed from the PHY's trace (energy/radio_states.h) for the energy by state.
#pragma once

#include <ns3/net-device.h>
#include <ns3/node.h>
#include <ns3/wifi-net-device.h>
#include <ns3/wifi-radio-energy-model.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "energy/battery.h"
#include "energy/electronics_model.h"
#include "energy/energy_spec.h"
#include "energy/li_ion_cell.h"
#include "energy/radio_energy_model.h"
#include "energy/radio_states.h"
#include "sanet/readings.h"

namespace sanet::energy {

// Joules used, by component, in the order summary.json lists them.
using EnergyUse = std::vector<std::pair<std::string, double>>;

class NodeEnergy {
 public:
  struct Hooks {
    std::function<void()> depleted;  // the charge fell to the cutoff
    std::function<void()> revived;   // a dead node's charge rose above RevivesAbove
  };
  // `radio`: the node's Wi-Fi device, or null (a run without a network).
  NodeEnergy(const EnergySpec& spec, ns3::Ptr<ns3::Node> node, ns3::Ptr<ns3::NetDevice> radio, Hooks hooks);
  ~NodeEnergy();
  NodeEnergy(const NodeEnergy&) = delete;
  NodeEnergy& operator=(const NodeEnergy&) = delete;

  const EnergySpec& spec() const { return spec_; }
  BatteryReading Reading() const;
  double remaining_j() const { return source_->GetRemainingEnergy(); }
  double power_w() const;  // drawn now
  EnergyUse Used() const;
  // Seconds the radio spent in each state by the PHY's own trace ("tx", "rx", "idle", "cca_busy",
  // "sleep"); empty without a radio.
  EnergyUse RadioSeconds() const;
  double charged_j() const { return charged_j_; }
  bool depleted() const { return rechargeable_->depleted(); }
  // Adds up to `joules` (never past full); returns what the battery took.
  double Recharge(double joules);
  // The electronics draw only while the node is on (alive and not switched off).
  void SetOn(bool on) { electronics_->SetOn(on); }
  // The radio is on again after an off (a revival).
  void RadioSwitchedOn();

 private:
  void InstallRadio(ns3::Ptr<ns3::NetDevice> radio);

  EnergySpec spec_;
  Hooks hooks_;
  void MakeSource(ns3::Ptr<ns3::Node> node);
  double MostWatts() const;

  ns3::Ptr<ns3::EnergySource> source_;  // a Battery or a LiIonCell, as the spec says
  Rechargeable* rechargeable_ = nullptr;
  ns3::Ptr<ElectronicsModel> electronics_;
  ns3::Ptr<RadioEnergyModel> radio_;            // the radio's model since it was last switched on
  RadioEnergyModel::ByState earlier_radios_{};  // what the models before it charged
  ns3::Ptr<ns3::WifiNetDevice> radio_device_;
  std::unique_ptr<RadioStates> states_;
  double charged_j_ = 0;
  bool has_radio_ = false;
};

}  // namespace sanet::energy
