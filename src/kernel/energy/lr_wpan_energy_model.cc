#include "energy/lr_wpan_energy_model.h"

#include <ns3/lr-wpan-mac.h>
#include <ns3/lr-wpan-phy.h>
#include <ns3/simulator.h>

namespace sanet::energy {

NS_OBJECT_ENSURE_REGISTERED(LrWpanEnergyModel);

ns3::TypeId LrWpanEnergyModel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::energy::LrWpanEnergyModel")
                               .SetParent<ns3::DeviceEnergyModel>()
                               .SetGroupName("Energy")
                               .AddConstructor<LrWpanEnergyModel>();
  return tid;
}

void LrWpanEnergyModel::Attach(ns3::Ptr<ns3::LrWpanNetDevice> device, std::function<bool()> sleeping) {
  sleeping_ = std::move(sleeping);
  tally_.Start();
  state_ = StateOf(phy_state_);
  device->GetPhy()->TraceConnectWithoutContext(
      "TrxState",
      ns3::Callback<void, ns3::Time, ns3::LrWpanPhyEnumeration, ns3::LrWpanPhyEnumeration>(
          [this](ns3::Time, ns3::LrWpanPhyEnumeration, ns3::LrWpanPhyEnumeration now) { PhyChanged(now); }));
}

LrWpanEnergyModel::State LrWpanEnergyModel::StateOf(ns3::LrWpanPhyEnumeration phy) const {
  switch (phy) {
    case ns3::IEEE_802_15_4_PHY_BUSY_TX:
    case ns3::IEEE_802_15_4_PHY_TX_ON:
      return kTx;
    case ns3::IEEE_802_15_4_PHY_BUSY_RX:
      return kRx;
    default:
      break;
  }
  if (sleeping_ && sleeping_()) return kSleep;
  return phy == ns3::IEEE_802_15_4_PHY_RX_ON ? kRx : kIdle;
}

void LrWpanEnergyModel::PhyChanged(ns3::LrWpanPhyEnumeration state) {
  phy_state_ = state;
  if (on_) Enter(StateOf(state));
}

void LrWpanEnergyModel::SetOn(bool on) {
  on_ = on;
  Enter(on ? StateOf(phy_state_) : kOff);
}

// The source drains what was drawn in the old state before the new one's current applies, then
// sees the new one (sanet's battery schedules its checks for it).
void LrWpanEnergyModel::Enter(State state) {
  if (source_) source_->UpdateEnergySource();
  tally_.Leave(state_, CurrentOf(state_), Volts());
  state_ = state;
  if (source_) source_->UpdateEnergySource();
}

double LrWpanEnergyModel::CurrentOf(State state) const {
  switch (state) {
    case kTx:
      return currents_.tx_a;
    case kRx:
      return currents_.rx_a;
    case kIdle:
      return currents_.idle_a;
    case kSleep:
      return currents_.sleep_a;
    default:
      return 0;
  }
}

LrWpanEnergyModel::ByState LrWpanEnergyModel::JoulesByState() const {
  return tally_.Joules(state_, CurrentOf(state_), Volts());
}

LrWpanEnergyModel::ByState LrWpanEnergyModel::SecondsByState() const { return tally_.Seconds(state_); }

double LrWpanEnergyModel::GetTotalEnergyConsumption() const {
  double total = 0;
  for (double j : JoulesByState()) total += j;
  return total;
}

}  // namespace sanet::energy
