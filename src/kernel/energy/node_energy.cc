#include "energy/node_energy.h"

#include <ns3/wifi-net-device.h>
#include <ns3/wifi-radio-energy-model-helper.h>

namespace sanet::energy {
namespace {

void Ignore() {}

}  // namespace

NodeEnergy::NodeEnergy(const EnergySpec& spec, ns3::Ptr<ns3::Node> node, ns3::Ptr<ns3::NetDevice> radio, Hooks hooks)
    : spec_(spec), hooks_(std::move(hooks)) {
  battery_ = ns3::CreateObject<Battery>();
  battery_->SetNode(node);
  electronics_ = ns3::CreateObject<ElectronicsModel>();
  electronics_->SetEnergySource(battery_);
  electronics_->SetCallbacks([this] { hooks_.depleted(); }, [this] { hooks_.revived(); });
  battery_->AppendDeviceEnergyModel(electronics_);
  electronics_->SetPower(spec.electronics_w);
  battery_->Configure({spec.battery_j, spec.voltage, spec.initial_fraction, spec.cutoff, spec.RevivesAbove()});
  if (radio) InstallRadio(radio);
  // Last, with every model in place: a battery that starts at its cutoff is depleted at once.
  battery_->Start();
}

NodeEnergy::~NodeEnergy() { battery_->Dispose(); }

// ns-3's helper connects the model to the PHY's states; depletion and recharge are the node's to
// handle (sim switches the whole node off), so the radio's own callbacks do nothing.
void NodeEnergy::InstallRadio(ns3::Ptr<ns3::NetDevice> radio) {
  ns3::WifiRadioEnergyModelHelper helper;
  const RadioCurrents& c = spec_.radio;
  helper.Set("TxCurrentA", ns3::DoubleValue(c.tx_a));
  helper.Set("RxCurrentA", ns3::DoubleValue(c.rx_a));
  helper.Set("IdleCurrentA", ns3::DoubleValue(c.idle_a));
  helper.Set("CcaBusyCurrentA", ns3::DoubleValue(c.cca_busy()));
  helper.Set("SwitchingCurrentA", ns3::DoubleValue(c.switching_a));
  helper.Set("SleepCurrentA", ns3::DoubleValue(c.sleep_a));
  helper.SetDepletionCallback(ns3::MakeCallback(&Ignore));
  helper.SetRechargedCallback(ns3::MakeCallback(&Ignore));
  ns3::DeviceEnergyModelContainer models = helper.Install(radio, battery_);
  radio_ = ns3::DynamicCast<ns3::WifiRadioEnergyModel>(models.Get(0));
  radio_device_ = ns3::DynamicCast<ns3::WifiNetDevice>(radio);
  if (!states_) states_ = std::make_unique<RadioStates>(radio_device_->GetPhy());
}

BatteryReading NodeEnergy::Reading() const {
  const double remaining = battery_->GetRemainingEnergy();
  return {remaining, remaining / spec_.battery_j, battery_->GetSupplyVoltage(), false, spec_.battery_j, power_w()};
}

double NodeEnergy::power_w() const {
  double amperes = electronics_->GetCurrentA();
  if (radio_) amperes += radio_->GetCurrentA();
  return amperes * battery_->GetSupplyVoltage();
}

EnergyUse NodeEnergy::Used() const {
  EnergyUse use;
  if (states_) {
    const RadioCurrents& c = spec_.radio;
    const double v = battery_->GetSupplyVoltage();
    const auto in = [&](::WifiPhyState s, double amperes) { return states_->SecondsIn(s) * amperes * v; };
    use = {{"radio_tx", in(::WifiPhyState::TX, c.tx_a)},
           {"radio_rx", in(::WifiPhyState::RX, c.rx_a)},
           {"radio_idle", in(::WifiPhyState::IDLE, c.idle_a)},
           {"radio_cca_busy", in(::WifiPhyState::CCA_BUSY, c.cca_busy())},
           {"radio_sleep", in(::WifiPhyState::SLEEP, c.sleep_a)}};
  }
  use.emplace_back("electronics", electronics_->GetTotalEnergyConsumption());
  return use;
}

double NodeEnergy::Recharge(double joules) {
  const double taken = battery_->Recharge(joules);
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
  InstallRadio(radio_device_);
}

}  // namespace sanet::energy
