#include "energy/radio_energy_model.h"

#include <ns3/energy-source.h>
#include <ns3/simulator.h>

#include "net/private_access.h"

namespace sanet::net {
// The model's pending switch to OFF, which ns-3 keeps private.
SANET_PRIVATE_MEMBER(RadioSwitchToOff, ns3::WifiRadioEnergyModel, ns3::EventId, m_switchToOffEvent);
}  // namespace sanet::net

namespace sanet::energy {

NS_OBJECT_ENSURE_REGISTERED(RadioEnergyModel);

ns3::TypeId RadioEnergyModel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::energy::RadioEnergyModel")
                               .SetParent<ns3::WifiRadioEnergyModel>()
                               .SetGroupName("Energy")
                               .AddConstructor<RadioEnergyModel>();
  return tid;
}

// Removing the switch that is running now (it calls this) does nothing: ns-3 sees it as expired.
RadioEnergyModel::ByState RadioEnergyModel::JoulesByState() const {
  ByState joules = joules_;
  const double seconds = (ns3::Simulator::Now() - since_).GetSeconds();
  if (source_ && seconds > 0)
    joules.at(static_cast<std::size_t>(GetCurrentState())) += seconds * GetCurrentA() * source_->GetSupplyVoltage();
  return joules;
}

void RadioEnergyModel::SetEnergySource(ns3::Ptr<ns3::EnergySource> source) {
  source_ = ns3::PeekPointer(source);
  ns3::WifiRadioEnergyModel::SetEnergySource(source);
}

// The state it leaves cost its current since it began; the source drains the same (it asks the
// models' currents, which change only here).
void RadioEnergyModel::ChangeState(int new_state) {
  joules_ = JoulesByState();
  since_ = ns3::Simulator::Now();
  ns3::Simulator::Remove(this->*Get(net::RadioSwitchToOff()));
  ns3::WifiRadioEnergyModel::ChangeState(new_state);
  if (source_) source_->UpdateEnergySource();
}

}  // namespace sanet::energy
