#include "energy/airtime_energy_model.h"

#include <ns3/simulator.h>

#include <algorithm>

namespace sanet::energy {

NS_OBJECT_ENSURE_REGISTERED(AirtimeEnergyModel);

ns3::TypeId AirtimeEnergyModel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::energy::AirtimeEnergyModel")
                               .SetParent<ns3::DeviceEnergyModel>()
                               .SetGroupName("Energy")
                               .AddConstructor<AirtimeEnergyModel>();
  return tid;
}

void AirtimeEnergyModel::DoDispose() {
  next_.Cancel();
  ns3::DeviceEnergyModel::DoDispose();
}

void AirtimeEnergyModel::OnAir(bool sent, double seconds) {
  ns3::Time& until = sent ? tx_until_ : rx_until_;
  until = std::max(until, ns3::Simulator::Now() + ns3::Seconds(seconds));
  Update();
}

void AirtimeEnergyModel::SetOn(bool on) {
  on_ = on;
  Update();
}

AirtimeEnergyModel::State AirtimeEnergyModel::Due() const {
  const ns3::Time now = ns3::Simulator::Now();
  if (!on_) return kOff;
  if (now < tx_until_) return kTx;
  return now < rx_until_ ? kRx : kIdle;
}

void AirtimeEnergyModel::Update() {
  Enter(Due());
  next_.Cancel();
  const ns3::Time now = ns3::Simulator::Now();
  const ns3::Time end = state_ == kTx ? tx_until_ : state_ == kRx ? rx_until_ : now;
  if (end > now) next_ = ns3::Simulator::Schedule(end - now, &AirtimeEnergyModel::Update, this);
}

// The source drains what was drawn in the old state before the new one's current applies.
void AirtimeEnergyModel::Enter(State state) {
  if (state == state_ && ns3::Simulator::Now() == tally_.since()) return;
  if (source_) source_->UpdateEnergySource();
  tally_.Leave(state_, CurrentOf(state_), Volts());
  state_ = state;
  if (source_) source_->UpdateEnergySource();
}

double AirtimeEnergyModel::CurrentOf(State state) const {
  switch (state) {
    case kTx:
      return currents_.tx_a;
    case kRx:
      return currents_.rx_a;
    case kIdle:
      return currents_.idle_a;
    default:
      return 0;
  }
}

AirtimeEnergyModel::ByState AirtimeEnergyModel::JoulesByState() const {
  return tally_.Joules(state_, CurrentOf(state_), Volts());
}

AirtimeEnergyModel::ByState AirtimeEnergyModel::SecondsByState() const { return tally_.Seconds(state_); }

double AirtimeEnergyModel::GetTotalEnergyConsumption() const {
  double total = 0;
  for (double j : JoulesByState()) total += j;
  return total;
}

}  // namespace sanet::energy
