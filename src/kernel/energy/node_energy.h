// One node's energy on ns-3's energy framework: its battery (energy/battery.h), the electronics'
// draw (energy/electronics_model.h) and, on a node with a Wi-Fi radio, ns-3's
// WifiRadioEnergyModel (energy/radio_energy_model.h) driven by the PHY's real states, with the time in each state
// summed from the PHY's trace (energy/radio_states.h) for the energy by state. A robot's drive
// draws its idle power as a constant model and its wheels' work as it is done (Drove); sensors
// draw their power as a constant model and their readings' energy as they are taken; a
// harvester (energy/charge_harvester.h) puts in what chargers give.
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

#include "energy/airtime_energy_model.h"
#include "energy/battery.h"
#include "energy/charge_harvester.h"
#include "energy/electronics_model.h"
#include "energy/energy_spec.h"
#include "energy/li_ion_cell.h"
#include "energy/lr_wpan_energy_model.h"
#include "energy/radio_energy_model.h"
#include "energy/radio_states.h"
#include "net/lr_wpan_radios.h"
#include "sanet/readings.h"

namespace sanet::energy {

// Joules used, by component, in the order summary.json lists them.
using EnergyUse = std::vector<std::pair<std::string, double>>;

struct DriveTallySoFar {
  double motor_work_j = 0, weight_rolled_j = 0;
};

class NodeEnergy {
 public:
  struct Hooks {
    std::function<void()> depleted;  // the charge fell to the cutoff
    std::function<void()> revived;   // a dead node's charge rose above RevivesAbove
  };
  // The node's radios: its Wi-Fi device and its 802.15.4 device, either null where it has none.
  struct Radios {
    ns3::Ptr<ns3::NetDevice> wifi;
    ns3::Ptr<ns3::LrWpanNetDevice> lr_wpan;
    net::LrWpanRadios* lr_wpan_radios = nullptr;  // which says when the 802.15.4 radio sleeps
    NodeId id = 0;
    bool abstract_wifi = false;  // an 802.11 radio on the abstract channel: its draw by airtime
  };
  // `sensors_w`: what its sensors draw while it is on.
  NodeEnergy(const EnergySpec& spec, ns3::Ptr<ns3::Node> node, Radios radios, double sensors_w, Hooks hooks);
  ~NodeEnergy();
  NodeEnergy(const NodeEnergy&) = delete;
  NodeEnergy& operator=(const NodeEnergy&) = delete;

  const EnergySpec& spec() const { return spec_; }
  BatteryReading Reading() const;
  double remaining_j() const { return source_->GetRemainingEnergy(); }
  double power_w() const;  // drawn now
  EnergyUse Used() const;
  // Seconds the radio spent in each state by the PHY's own trace ("tx", "rx", "idle", "cca_busy",
  // "sleep"); an 802.15.4 radio's "tx", "rx", "idle", "sleep" (prefixed "lr_wpan_" beside an
  // 802.11 radio); empty without a radio.
  EnergyUse RadioSeconds() const;
  // A frame of the abstract radio on the air from now for `seconds` (sent or received).
  void AbstractRadioOnAir(bool sent, double seconds) {
    if (airtime_) airtime_->OnAir(sent, seconds);
  }
  // Put in by recharges and chargers.
  double charged_j() const { return charged_j_ + rechargeable_->harvested_j(); }
  // The drive's tally so far (physics::DriveTally's two sums, J): what it did since the last call
  // is drawn now, over the drive's efficiency, in the `dt` seconds it took.
  void Drove(double motor_work_j, double weight_rolled_j, double dt);
  // Takes what the wheels' work still owes the battery (Drove takes it once it reaches
  // kOwedShare of the capacity): before a sample, a switch-off and at the run's end.
  void SettleMotion();
  // A sensor reading that costs `joules`.
  void SensorRead(double joules);
  // The power chargers give the node now, W.
  void SetCharging(double watts) { harvester_->SetPower(watts); }
  double charging_w() const { return harvester_->GetPower(); }
  // A robot's wireless charger radiates (drawing its power_w) or not.
  void SetRadiating(bool on);
  bool full() const { return remaining_j() >= spec_.battery_j * (1 - 1e-12); }
  bool depleted() const { return rechargeable_->depleted(); }
  // Adds up to `joules` (never past full); returns what the battery took.
  double Recharge(double joules);
  // The electronics draw only while the node is on (alive and not switched off).
  void SetOn(bool on);
  // The radio is on again after an off (a revival).
  void RadioSwitchedOn();

 private:
  void InstallRadio(ns3::Ptr<ns3::NetDevice> radio);
  void InstallAbstractRadio();

  EnergySpec spec_;
  Hooks hooks_;
  void MakeSource(ns3::Ptr<ns3::Node> node, double sensors_w);
  double MostWatts(double sensors_w) const;

  ns3::Ptr<ns3::EnergySource> source_;  // a Battery or a LiIonCell, as the spec says
  Rechargeable* rechargeable_ = nullptr;
  ns3::Ptr<ElectronicsModel> electronics_;
  ns3::Ptr<ElectronicsModel> drive_idle_;  // a robot's; null on a mote
  ns3::Ptr<ElectronicsModel> sensors_;
  ns3::Ptr<ChargeHarvester> harvester_;
  ns3::Ptr<ElectronicsModel> charger_;  // a robot's wireless charger; null without one
  bool radiating_ = false;
  bool on_ = true;  // alive and not switched off: what it does costs nothing otherwise
  // A battery update for every robot at every physics step cost a 1,000-robot swarm a third of its
  // speed; up to this share of the capacity is owed instead, and taken at once.
  static constexpr double kOwedShare = 1e-5;
  double motion_j_ = 0, motion_w_ = 0;  // the wheels' electrical energy, and its power in the last step
  double owed_j_ = 0;                   // of motion_j_, not taken from the battery yet
  double readings_j_ = 0;
  DriveTallySoFar drove_;
  ns3::Ptr<RadioEnergyModel> radio_;            // the radio's model since it was last switched on
  ns3::Ptr<AirtimeEnergyModel> airtime_;        // the abstract radio's, instead
  RadioEnergyModel::ByState earlier_radios_{};  // what the models before it charged
  ns3::Ptr<ns3::WifiNetDevice> radio_device_;
  std::unique_ptr<RadioStates> states_;
  ns3::Ptr<LrWpanEnergyModel> lr_wpan_;  // the 802.15.4 radio's, if the node has one
  std::string LrWpanPrefix() const { return radio_ || airtime_ ? "lr_wpan_" : "radio_"; }
  double charged_j_ = 0;
  bool has_radio_ = false;
};

}  // namespace sanet::energy
