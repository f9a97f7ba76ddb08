#include "energy/node_energy.h"

#include <ns3/wifi-net-device.h>

#include <algorithm>

namespace sanet::energy {
namespace {

void Ignore() {}

// A constant draw while the node is on, on `source`.
ns3::Ptr<ElectronicsModel> ConstantModel(ns3::Ptr<ns3::EnergySource> source, double watts) {
  auto model = ns3::CreateObject<ElectronicsModel>();
  model->SetEnergySource(source);
  source->AppendDeviceEnergyModel(model);
  model->SetPower(watts);
  return model;
}

}  // namespace

NodeEnergy::NodeEnergy(const EnergySpec& spec, ns3::Ptr<ns3::Node> node, Radios radios, double sensors_w, Hooks hooks)
    : spec_(spec), hooks_(std::move(hooks)), has_radio_(radios.wifi != nullptr || radios.abstract_wifi) {
  const ns3::Ptr<ns3::NetDevice> radio = radios.wifi;
  if (radios.lr_wpan && !spec_.lr_wpan_radio) spec_.lr_wpan_radio = {"cc2420", RadioPresetNamed("cc2420").currents};
  MakeSource(node, sensors_w);
  electronics_ = ConstantModel(source_, spec.electronics_w);
  electronics_->SetCallbacks([this] { hooks_.depleted(); }, [this] { hooks_.revived(); });
  if (spec.drive) drive_idle_ = ConstantModel(source_, spec.drive->idle_w);
  sensors_ = ConstantModel(source_, sensors_w);
  if (spec.wireless_charger) charger_ = ConstantModel(source_, 0);
  harvester_ = ns3::CreateObject<ChargeHarvester>();
  harvester_->SetNode(node);
  rechargeable_->AddHarvester(harvester_);
  if (radio) InstallRadio(radio);
  if (radios.abstract_wifi) InstallAbstractRadio();
  if (radios.lr_wpan) {
    lr_wpan_ = ns3::CreateObject<LrWpanEnergyModel>();
    lr_wpan_->SetCurrents(spec_.lr_wpan_radio->currents);
    lr_wpan_->SetEnergySource(source_);
    source_->AppendDeviceEnergyModel(lr_wpan_);
    net::LrWpanRadios* lr = radios.lr_wpan_radios;
    const NodeId id = radios.id;
    lr_wpan_->Attach(radios.lr_wpan, [lr, id] { return lr && lr->Sleeping(id); });
    if (lr) lr->OnSleepChange(id, [model = ns3::PeekPointer(lr_wpan_)] { model->SleepChanged(); });
  }
  // Last, with every model in place: a battery that starts at its cutoff is depleted at once.
  rechargeable_->Start();
}

NodeEnergy::~NodeEnergy() { source_->Dispose(); }

void NodeEnergy::MakeSource(ns3::Ptr<ns3::Node> node, double sensors_w) {
  if (spec_.source == Chemistry::kLiIon) {
    auto cell = ns3::CreateObject<LiIonCell>();
    cell->Configure(spec_.battery_j, spec_.initial_fraction, spec_.cutoff, spec_.RevivesAbove());
    rechargeable_ = ns3::PeekPointer(cell);
    source_ = cell;
  } else {
    auto battery = ns3::CreateObject<Battery>();
    battery->Configure({spec_.battery_j, spec_.voltage, spec_.initial_fraction, spec_.cutoff, spec_.RevivesAbove(),
                        MostWatts(sensors_w)});
    rechargeable_ = ns3::PeekPointer(battery);
    source_ = battery;
  }
  source_->SetNode(node);
}

// The radio's largest current (whatever its state) and the constant draws together. The wheels'
// work is taken as it is done (Take), which checks the charge itself.
double NodeEnergy::MostWatts(double sensors_w) const {
  const RadioCurrents& c = spec_.radio;
  const double radio_a = has_radio_ ? std::max({c.tx_a, c.rx_a, c.idle_a, c.cca_busy(), c.switching_a, c.sleep_a}) : 0;
  const RadioCurrents* l = spec_.lr_wpan_radio ? &spec_.lr_wpan_radio->currents : nullptr;
  const double lr_wpan_a = l ? std::max({l->tx_a, l->rx_a, l->idle_a, l->sleep_a}) : 0;
  return (radio_a + lr_wpan_a) * spec_.voltage + spec_.electronics_w + (spec_.drive ? spec_.drive->idle_w : 0) +
         sensors_w + (spec_.wireless_charger ? spec_.wireless_charger->power_w : 0);
}

void NodeEnergy::SetOn(bool on) {
  if (!on) SettleMotion();
  on_ = on;
  electronics_->SetOn(on);
  if (lr_wpan_) lr_wpan_->SetOn(on);
  if (airtime_) airtime_->SetOn(on);
  if (drive_idle_) drive_idle_->SetOn(on);
  sensors_->SetOn(on);
  if (charger_) charger_->SetOn(on);
  if (!on) motion_w_ = 0;
}

void NodeEnergy::SetRadiating(bool on) {
  if (!charger_ || on == radiating_) return;
  radiating_ = on;
  charger_->SetPower(on ? spec_.wireless_charger->power_w : 0);
}

void NodeEnergy::Drove(double motor_work_j, double weight_rolled_j, double dt) {
  if (!spec_.drive) return;
  const DriveCosts& d = *spec_.drive;
  const double work_j =
      (motor_work_j - drove_.motor_work_j) + d.rolling_resistance * (weight_rolled_j - drove_.weight_rolled_j);
  drove_ = {motor_work_j, weight_rolled_j};
  const double electrical_j = on_ ? work_j / d.efficiency : 0;
  motion_w_ = dt > 0 ? electrical_j / dt : 0;
  owed_j_ += electrical_j;
  if (owed_j_ >= kOwedShare * spec_.battery_j) SettleMotion();
}

void NodeEnergy::SettleMotion() {
  if (owed_j_ <= 0) return;
  motion_j_ += rechargeable_->Take(owed_j_);
  owed_j_ = 0;
}

void NodeEnergy::SensorRead(double joules) {
  if (joules > 0 && on_) readings_j_ += rechargeable_->Take(joules);
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

void NodeEnergy::InstallAbstractRadio() {
  airtime_ = ns3::CreateObject<AirtimeEnergyModel>();
  airtime_->SetCurrents(spec_.radio);
  airtime_->SetEnergySource(source_);
  source_->AppendDeviceEnergyModel(airtime_);
}

// Charging while chargers give it something and it is not full; the power is what it draws less
// what they give (a full battery takes no more than it draws: then none).
BatteryReading NodeEnergy::Reading() const {
  const double remaining = source_->GetRemainingEnergy();
  const double fraction = remaining / spec_.battery_j;
  const bool charging = charging_w() > 0 && !full();
  const double net_w = power_w() - charging_w();
  return {remaining, fraction,        source_->GetSupplyVoltage(),
          charging,  spec_.battery_j, full() ? std::max(0.0, net_w) : net_w};
}

double NodeEnergy::power_w() const {
  double amperes = electronics_->GetCurrentA() + sensors_->GetCurrentA();
  if (drive_idle_) amperes += drive_idle_->GetCurrentA();
  if (charger_) amperes += charger_->GetCurrentA();
  if (radio_) amperes += radio_->GetCurrentA();
  if (airtime_) amperes += airtime_->GetCurrentA();
  if (lr_wpan_) amperes += lr_wpan_->GetCurrentA();
  return amperes * source_->GetSupplyVoltage() + motion_w_;
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
  if (airtime_) {
    const AirtimeEnergyModel::ByState joules = airtime_->JoulesByState();
    for (int s = AirtimeEnergyModel::kTx; s < AirtimeEnergyModel::kOff; ++s)
      use.emplace_back(std::string("radio_") + AirtimeEnergyModel::kStateNames[s], joules[s]);
  }
  if (lr_wpan_) {
    const LrWpanEnergyModel::ByState joules = lr_wpan_->JoulesByState();
    for (int s = LrWpanEnergyModel::kTx; s < LrWpanEnergyModel::kOff; ++s)
      use.emplace_back(LrWpanPrefix() + LrWpanEnergyModel::kStateNames[s], joules[s]);
  }
  use.emplace_back("electronics", electronics_->GetTotalEnergyConsumption());
  use.emplace_back("motion", (drive_idle_ ? drive_idle_->GetTotalEnergyConsumption() : 0) + motion_j_);
  use.emplace_back("sensors", sensors_->GetTotalEnergyConsumption() + readings_j_);
  if (charger_) use.emplace_back("wireless_charger", charger_->GetTotalEnergyConsumption());
  return use;
}

EnergyUse NodeEnergy::RadioSeconds() const {
  EnergyUse seconds;
  if (states_)
    for (const auto& [name, state] : kRadioStates) seconds.emplace_back(name, states_->SecondsIn(state));
  if (airtime_) {
    const AirtimeEnergyModel::ByState in_state = airtime_->SecondsByState();
    for (int s = AirtimeEnergyModel::kTx; s < AirtimeEnergyModel::kOff; ++s)
      seconds.emplace_back(AirtimeEnergyModel::kStateNames[s], in_state[s]);
  }
  if (lr_wpan_) {
    const std::string prefix = radio_ || airtime_ ? "lr_wpan_" : "";
    const LrWpanEnergyModel::ByState in_state = lr_wpan_->SecondsByState();
    for (int s = LrWpanEnergyModel::kTx; s < LrWpanEnergyModel::kOff; ++s)
      seconds.emplace_back(prefix + LrWpanEnergyModel::kStateNames[s], in_state[s]);
  }
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
