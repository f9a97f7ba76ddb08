#include "energy/node_energy.h"

#include <ns3/wifi-net-device.h>

#include <algorithm>

namespace sanet::energy {
namespace {

void Ignore() {}

}  // namespace

NodeEnergy::NodeEnergy(const EnergySpec& spec, ns3::Ptr<ns3::Node> node, ns3::Ptr<ns3::NetDevice> radio, Hooks hooks)
    : spec_(spec), hooks_(std::move(hooks)), has_radio_(radio != nullptr) {
  MakeSource(node);
  electronics_ = ns3::CreateObject<ElectronicsModel>();
  electronics_->SetEnergySource(source_);
  electronics_->SetCallbacks([this] { hooks_.depleted(); }, [this] { hooks_.revived(); });
  source_->AppendDeviceEnergyModel(electronics_);
  electronics_->SetPower(spec.electronics_w);
  if (radio) InstallRadio(radio);
  // Last, with every model in place: a battery that starts at its cutoff is depleted at once.
  rechargeable_->Start();
}

NodeEnergy::~NodeEnergy() { source_->Dispose(); }

void NodeEnergy::MakeSource(ns3::Ptr<ns3::Node> node) {
  if (spec_.source == Chemistry::kLiIon) {
    auto cell = ns3::CreateObject<LiIonCell>();
    cell->Configure(spec_.battery_j, spec_.initial_fraction, spec_.cutoff, spec_.RevivesAbove());
    rechargeable_ = ns3::PeekPointer(cell);
    source_ = cell;
  } else {
    auto battery = ns3::CreateObject<Battery>();
    battery->Configure(
        {spec_.battery_j, spec_.voltage, spec_.initial_fraction, spec_.cutoff, spec_.RevivesAbove(), MostWatts()});
    rechargeable_ = ns3::PeekPointer(battery);
    source_ = battery;
  }
  source_->SetNode(node);
}

// The radio's largest current (whatever its state) and the electronics together.
double NodeEnergy::MostWatts() const {
  const RadioCurrents& c = spec_.radio;
  const double radio_a = has_radio_ ? std::max({c.tx_a, c.rx_a, c.idle_a, c.cca_busy(), c.switching_a, c.sleep_a}) : 0;
  return radio_a * spec_.voltage + spec_.electronics_w;
}

// Installed as ns-3's WifiRadioEnergyModelHelper installs its model (the PHY's listener, the
// source's list, the PHY's model), but the model is sanet's RadioEnergyModel, which the helper
// cannot make. Depletion and recharge are the node's to handle (sim switches the whole node off),
// so the radio's own callbacks do nothing.
void NodeEnergy::InstallRadio(ns3::Ptr<ns3::NetDevice> radio) {
  const RadioCurrents& c = spec_.radio;
  radio_ = ns3::CreateObject<RadioEnergyModel>();
  radio_->SetTxCurrentA(c.tx_a);
  radio_->SetRxCurrentA(c.rx_a);
  radio_->SetIdleCurrentA(c.idle_a);
  radio_->SetCcaBusyCurrentA(c.cca_busy());
  radio_->SetSwitchingCurrentA(c.switching_a);
  radio_->SetSleepCurrentA(c.sleep_a);
  radio_->SetEnergyDepletionCallback(ns3::MakeCallback(&Ignore));
  radio_->SetEnergyRechargedCallback(ns3::MakeCallback(&Ignore));
  radio_->SetEnergySource(source_);
  source_->AppendDeviceEnergyModel(radio_);
  radio_device_ = ns3::DynamicCast<ns3::WifiNetDevice>(radio);
  ns3::Ptr<ns3::WifiPhy> phy = radio_device_->GetPhy();
  phy->SetWifiRadioEnergyModel(radio_);
  phy->RegisterListener(radio_->GetPhyListener());
  if (!states_) states_ = std::make_unique<RadioStates>(phy);
}

BatteryReading NodeEnergy::Reading() const {
  const double remaining = source_->GetRemainingEnergy();
  return {remaining, remaining / spec_.battery_j, source_->GetSupplyVoltage(), false, spec_.battery_j, power_w()};
}

double NodeEnergy::power_w() const {
  double amperes = electronics_->GetCurrentA();
  if (radio_) amperes += radio_->GetCurrentA();
  return amperes * source_->GetSupplyVoltage();
}

namespace {

constexpr std::pair<const char*, ::WifiPhyState> kRadioStates[] = {{"tx", ::WifiPhyState::TX},
                                                                   {"rx", ::WifiPhyState::RX},
                                                                   {"idle", ::WifiPhyState::IDLE},
                                                                   {"cca_busy", ::WifiPhyState::CCA_BUSY},
                                                                   {"sleep", ::WifiPhyState::SLEEP}};

}  // namespace

EnergyUse NodeEnergy::Used() const {
  EnergyUse use;
  if (radio_) {
    RadioEnergyModel::ByState joules = radio_->JoulesByState();
    for (std::size_t s = 0; s < joules.size(); ++s) joules[s] += earlier_radios_[s];
    for (const auto& [name, state] : kRadioStates)
      use.emplace_back(std::string("radio_") + name, joules[static_cast<std::size_t>(state)]);
  }
  use.emplace_back("electronics", electronics_->GetTotalEnergyConsumption());
  return use;
}

EnergyUse NodeEnergy::RadioSeconds() const {
  EnergyUse seconds;
  if (states_)
    for (const auto& [name, state] : kRadioStates) seconds.emplace_back(name, states_->SecondsIn(state));
  return seconds;
}

double NodeEnergy::Recharge(double joules) {
  const double taken = rechargeable_->Recharge(joules);
  charged_j_ += taken;
  return taken;
}

void NodeEnergy::RadioSwitchedOn() {
  if (!radio_) return;
  states_->SwitchedOn();
  // ns-3's WifiRadioEnergyModel never leaves its OFF state (ChangeState keeps OFF once in it), so
  // the radio that came back gets a model of its own; the old one, off, draws nothing from now on.
  ns3::Ptr<ns3::WifiPhy> phy = radio_device_->GetPhy();
  phy->UnregisterListener(radio_->GetPhyListener());
  const RadioEnergyModel::ByState joules = radio_->JoulesByState();
  for (std::size_t s = 0; s < joules.size(); ++s) earlier_radios_[s] += joules[s];
  InstallRadio(radio_device_);
}

}  // namespace sanet::energy
