#include "energy/battery.h"

#include <ns3/simulator.h>

#include <algorithm>
#include <cmath>

namespace sanet::energy {

NS_OBJECT_ENSURE_REGISTERED(Battery);

ns3::TypeId Battery::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::energy::Battery")
                               .SetParent<ns3::EnergySource>()
                               .SetGroupName("Energy")
                               .AddConstructor<Battery>();
  return tid;
}

void Battery::Configure(const Settings& settings) {
  settings_ = settings;
  remaining_j_ = settings.capacity_j * settings.initial_fraction;
}

void Battery::Start() {
  started_ = true;
  last_update_ = ns3::Simulator::Now();
  CheckThresholds();  // a battery that starts at its cutoff is depleted from the start
  ScheduleNextUpdate();
}

double Battery::GetRemainingEnergy() {
  UpdateEnergySource();
  return remaining_j_;
}

void Battery::UpdateEnergySource() {
  if (!started_ || ns3::Simulator::IsFinished()) return;
  Drain();
  CheckThresholds();
  ScheduleNextUpdate();
}

double Battery::Recharge(double joules) {
  UpdateEnergySource();
  if (!started_) return 0;
  const double taken = std::clamp(settings_.capacity_j - remaining_j_, 0.0, joules);
  remaining_j_ += taken;
  CheckThresholds();
  ScheduleNextUpdate();
  return taken;
}

void Battery::Drain() {
  const ns3::Time now = ns3::Simulator::Now();
  const double seconds = (now - last_update_).GetSeconds();
  last_update_ = now;
  if (seconds > 0) remaining_j_ = std::max(0.0, remaining_j_ - CalculateTotalCurrent() * settings_.voltage * seconds);
}

// The models hear it first thing: they change their current (and ask for an update, which finds
// nothing more to drain) before this returns.
void Battery::CheckThresholds() {
  // A nanojoule's slack per joule: the update scheduled for the cutoff lands on it, not a hair above.
  const double slack = 1e-9 * settings_.capacity_j;
  if (!depleted_ && remaining_j_ <= settings_.cutoff * settings_.capacity_j + slack) {
    depleted_ = true;
    NotifyEnergyDrained();
  } else if (depleted_ && remaining_j_ > settings_.revives_above * settings_.capacity_j) {
    depleted_ = false;
    NotifyEnergyRecharged();
  }
}

// At the current draw the charge reaches the cutoff after (remaining - cutoff) / (I V) seconds;
// the update is due then, rounded up to ns-3's nanosecond.
void Battery::ScheduleNextUpdate() {
  next_update_.Cancel();
  if (depleted_) return;
  const double watts = CalculateTotalCurrent() * settings_.voltage;
  if (watts <= 0) return;
  const double seconds = (remaining_j_ - settings_.cutoff * settings_.capacity_j) / watts;
  const double ns = std::ceil(std::max(0.0, seconds) * 1e9);
  if (ns > 9e18) return;  // past any run
  next_update_ =
      ns3::Simulator::Schedule(ns3::NanoSeconds(static_cast<std::int64_t>(ns)), &Battery::UpdateEnergySource, this);
}

void Battery::DoDispose() {
  next_update_.Cancel();
  BreakDeviceEnergyModelRefCycle();
}

}  // namespace sanet::energy
