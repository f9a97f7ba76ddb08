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

// What remains now, without an update: a read changes nothing (so who reads, and whether the run
// still goes, changes no result), and the draw since the last update is the models' current one.
double Battery::GetRemainingEnergy() {
  const double seconds = (ns3::Simulator::Now() - last_update_).GetSeconds();
  if (!started_ || seconds <= 0) return remaining_j_;
  return std::max(0.0, remaining_j_ - CalculateTotalCurrent() * settings_.voltage * seconds);
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

// The models hear it at once; the node dies (or comes back) in an event of its own, at this instant.
void Battery::CheckThresholds() {
  // The checks close in on the cutoff from above: within a picojoule per joule of it, it is reached
  // (a nanosecond's draw more would cross it).
  const double cutoff_j = settings_.cutoff * settings_.capacity_j;
  if (!depleted_ && remaining_j_ <= cutoff_j + 1e-12 * settings_.capacity_j) {
    depleted_ = true;
    remaining_j_ = std::min(remaining_j_, cutoff_j);
    NotifyEnergyDrained();
  } else if (depleted_ && remaining_j_ >= settings_.revives_above * settings_.capacity_j) {
    depleted_ = false;
    NotifyEnergyRecharged();
  }
}

// At the most the models can draw, the charge reaches the cutoff after
// (remaining - cutoff) / most_watts seconds at the earliest, rounded up to ns-3's nanosecond. A
// check already due before then stands.
//
// Nothing is scheduled while nothing draws (a node switched off): each model asks for an update
// after its current changed as well as before (energy/radio_energy_model.h), which schedules it.
void Battery::ScheduleNextUpdate() {
  if (depleted_ || settings_.most_watts <= 0 || CalculateTotalCurrent() <= 0) return next_check_.Cancel();
  const double seconds = (remaining_j_ - settings_.cutoff * settings_.capacity_j) / settings_.most_watts;
  const double ns = std::ceil(std::max(0.0, seconds) * 1e9);
  if (ns > 9e18) return;  // past any run
  const ns3::Time at = ns3::Simulator::Now() + ns3::NanoSeconds(static_cast<std::int64_t>(ns));
  if (next_check_.IsRunning() && next_check_at_ <= at) return;
  next_check_.Cancel();
  next_check_at_ = at;
  next_check_ = ns3::Simulator::Schedule(at - ns3::Simulator::Now(), &Battery::UpdateEnergySource, this);
}

void Battery::DoDispose() {
  next_check_.Cancel();
  BreakDeviceEnergyModelRefCycle();
}

}  // namespace sanet::energy
