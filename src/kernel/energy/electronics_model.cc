#include "energy/electronics_model.h"

#include <ns3/simulator.h>

#include <utility>

namespace sanet::energy {

NS_OBJECT_ENSURE_REGISTERED(ElectronicsModel);

ns3::TypeId ElectronicsModel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::energy::ElectronicsModel")
                               .SetParent<ns3::DeviceEnergyModel>()
                               .SetGroupName("Energy")
                               .AddConstructor<ElectronicsModel>();
  return tid;
}

void ElectronicsModel::SetCallbacks(std::function<void()> depleted, std::function<void()> recharged) {
  depleted_ = std::move(depleted);
  recharged_ = std::move(recharged);
}

void ElectronicsModel::SetPower(double watts) { Change(watts, on_); }

void ElectronicsModel::SetOn(bool on) {
  if (on != on_) Change(watts_, on);
}

// The source drains what was drawn at the old current before the new one applies, then sees the
// new one (and schedules its checks for it).
void ElectronicsModel::Change(double watts, bool on) {
  Account();
  if (source_) source_->UpdateEnergySource();
  watts_ = watts;
  on_ = on;
  if (source_) source_->UpdateEnergySource();
}

double ElectronicsModel::GetTotalEnergyConsumption() const {
  const double since = (ns3::Simulator::Now() - last_).GetSeconds();
  return used_j_ + (on_ ? watts_ * since : 0);
}

void ElectronicsModel::Account() {
  used_j_ = GetTotalEnergyConsumption();
  last_ = ns3::Simulator::Now();
}

double ElectronicsModel::DoGetCurrentA() const { return on_ && source_ ? watts_ / source_->GetSupplyVoltage() : 0; }

void ElectronicsModel::HandleEnergyDepletion() {
  if (depleted_) depleted_();
}

void ElectronicsModel::HandleEnergyRecharged() {
  if (recharged_) recharged_();
}

}  // namespace sanet::energy
