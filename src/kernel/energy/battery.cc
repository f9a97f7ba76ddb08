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
  return std::clamp(ChargeAfter(seconds), 0.0, settings_.capacity_j);
}

// The charge `seconds` after the last update at the net draw since (neither floored nor capped).
double Battery::ChargeAfter(double seconds) {
  return remaining_j_ - CalculateTotalCurrent() * settings_.voltage * seconds;
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

double Battery::Take(double joules) {
  UpdateEnergySource();
  if (!started_ || depleted_) return 0;
  const double taken = std::clamp(joules, 0.0, remaining_j_);
  remaining_j_ -= taken;
  CheckThresholds();
  ScheduleNextUpdate();
  return taken;
}

void Battery::AddHarvester(ns3::Ptr<ChargeHarvester> harvester) {
  UpdateEnergySource();
  harvesters_.Add(*this, harvester);
  UpdateEnergySource();
}

// Up to now without an update, as GetRemainingEnergy: after the run ns-3 has finished and updates
// no more.
double Battery::harvested_j() {
  const double seconds = (ns3::Simulator::Now() - last_update_).GetSeconds();
  if (!started_ || seconds <= 0) return harvested_j_;
  return harvested_j_ + harvesters_.Gave(seconds, std::max(0.0, ChargeAfter(seconds) - settings_.capacity_j));
}

// The draw less the harvest, constant since the last update; what would go past full is lost.
void Battery::Drain() {
  const ns3::Time now = ns3::Simulator::Now();
  const double seconds = (now - last_update_).GetSeconds();
  last_update_ = now;
  if (seconds <= 0) return;
  const double after = ChargeAfter(seconds);
  const double lost = std::max(0.0, after - settings_.capacity_j);
  remaining_j_ = std::clamp(after, 0.0, settings_.capacity_j);
  harvested_j_ += harvesters_.Gave(seconds, lost);
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
  const double net_w = CalculateTotalCurrent() * settings_.voltage;
  if (net_w < 0) return ScheduleWhileCharging(-net_w);
  if (depleted_ || settings_.most_watts <= 0 || net_w <= 0) return next_check_.Cancel();
  ScheduleCheckIn((remaining_j_ - settings_.cutoff * settings_.capacity_j) / settings_.most_watts);
}

// At the gain it has now, the charge reaches the revive level (a dead battery) or full then; a
// full battery has nothing to wait for.
void Battery::ScheduleWhileCharging(double gain_w) {
  const double target_j = (depleted_ ? settings_.revives_above : 1.0) * settings_.capacity_j;
  if (remaining_j_ >= target_j) return next_check_.Cancel();
  ScheduleCheckIn((target_j - remaining_j_) / gain_w);
}

void Battery::ScheduleCheckIn(double seconds) {
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
