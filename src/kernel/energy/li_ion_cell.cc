#include "energy/li_ion_cell.h"

#include <ns3/double.h>
#include <ns3/simulator.h>

#include <algorithm>

#include "net/private_access.h"

namespace sanet::net {
// ns-3 keeps the drained capacity, which sets the cell's voltage, private and offers no setter.
SANET_PRIVATE_MEMBER(LiIonDrainedAh, ns3::LiIonEnergySource, double, m_drainedCapacity);
// Its charge and its last update, read without the update GetRemainingEnergy makes; the last update
// is set when a pack starts after the run did (a robot spawned later), which ns-3 takes as 0.
SANET_PRIVATE_MEMBER(LiIonRemainingJ, ns3::LiIonEnergySource, ns3::TracedValue<double>, m_remainingEnergyJ);
SANET_PRIVATE_MEMBER(LiIonLastUpdate, ns3::LiIonEnergySource, ns3::Time, m_lastUpdateTime);
}  // namespace sanet::net

namespace sanet::energy {

NS_OBJECT_ENSURE_REGISTERED(LiIonCell);

namespace {
constexpr double kNominalVoltage = 3.6;  // V: joules to ampere-hours, as ns-3's default cell is rated
}  // namespace

ns3::TypeId LiIonCell::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::energy::LiIonCell")
                               .SetParent<ns3::LiIonEnergySource>()
                               .SetGroupName("Energy")
                               .AddConstructor<LiIonCell>();
  return tid;
}

double& LiIonCell::DrainedAh() { return this->*Get(net::LiIonDrainedAh()); }

void LiIonCell::Configure(double capacity_j, double initial_fraction, double cutoff, double revives_above) {
  capacity_j_ = capacity_j, cutoff_ = cutoff, revives_above_ = revives_above;
  const double k = capacity_j / kDefaultCellJ;  // cells of ns-3's default in parallel
  SetAttribute("LiIonEnergySourceInitialEnergyJ", ns3::DoubleValue(capacity_j));
  // Below any charge: the cell decides when it is depleted (CheckThresholds), once.
  SetAttribute("LiIonEnergyLowBatteryThreshold", ns3::DoubleValue(-1));
  SetAttribute("RatedCapacity", ns3::DoubleValue(2.45 * k));
  SetAttribute("NomCapacity", ns3::DoubleValue(1.1 * k));
  SetAttribute("ExpCapacity", ns3::DoubleValue(1.2 * k));
  SetAttribute("TypCurrent", ns3::DoubleValue(2.33 * k));
  SetAttribute("InternalResistance", ns3::DoubleValue(0.083 / k));
  const double drained_j = (1 - initial_fraction) * capacity_j;
  DecreaseRemainingEnergy(drained_j);
  DrainedAh() = drained_j / (kNominalVoltage * 3600);
}

void LiIonCell::Start() {
  started_ = true;
  this->*Get(net::LiIonLastUpdate()) = ns3::Simulator::Now();
  Initialize();  // ns-3's periodic updates start here
  CheckThresholds();
}

// Once the simulator has finished, ns-3's update does nothing (the time of the last stays): nor
// does this one, so that nothing is counted twice.
void LiIonCell::UpdateEnergySource() {
  if (!started_ || ns3::Simulator::IsFinished()) return;
  const double harvested_w = harvesters_.Watts();
  const double seconds = (ns3::Simulator::Now() - this->*Get(net::LiIonLastUpdate())).GetSeconds();
  ns3::LiIonEnergySource::UpdateEnergySource();
  KeepBelowFull(harvested_w, seconds);
  CheckThresholds(/*recharged=*/harvested_w > 0);
}

void LiIonCell::KeepBelowFull(double harvested_w, double seconds) {
  if (harvested_w <= 0 || seconds <= 0) return;
  ns3::TracedValue<double>& remaining = this->*Get(net::LiIonRemainingJ());
  const double lost = std::max(0.0, remaining.Get() - capacity_j_);
  if (lost > 0) remaining = capacity_j_;
  DrainedAh() = std::max(0.0, DrainedAh());
  harvested_j_ += std::max(0.0, harvested_w * seconds - lost);
}

double LiIonCell::GetRemainingEnergy() {
  const double remaining = this->*Get(net::LiIonRemainingJ());
  const double seconds = (ns3::Simulator::Now() - this->*Get(net::LiIonLastUpdate())).GetSeconds();
  if (!started_ || seconds <= 0) return remaining;
  return std::clamp(ChargeAfter(seconds), 0.0, capacity_j_);
}

// The charge `seconds` after the last update at the net draw since (neither floored nor capped).
double LiIonCell::ChargeAfter(double seconds) {
  return this->*Get(net::LiIonRemainingJ()) - CalculateTotalCurrent() * GetSupplyVoltage() * seconds;
}

double LiIonCell::Take(double joules) {
  UpdateEnergySource();
  if (depleted_) return 0;
  const double taken = std::clamp(joules, 0.0, GetRemainingEnergy());
  DecreaseRemainingEnergy(taken);
  DrainedAh() += taken / (kNominalVoltage * 3600);
  UpdateEnergySource();  // the voltage at the new charge
  CheckThresholds();
  return taken;
}

void LiIonCell::AddHarvester(ns3::Ptr<ChargeHarvester> harvester) {
  UpdateEnergySource();
  harvesters_.Add(*this, harvester);
}

// Up to now without an update, as GetRemainingEnergy.
double LiIonCell::harvested_j() {
  const double seconds = (ns3::Simulator::Now() - this->*Get(net::LiIonLastUpdate())).GetSeconds();
  if (!started_ || seconds <= 0) return harvested_j_;
  return harvested_j_ + harvesters_.Gave(seconds, std::max(0.0, ChargeAfter(seconds) - capacity_j_));
}

double LiIonCell::Recharge(double joules) {
  UpdateEnergySource();
  const double taken = std::clamp(capacity_j_ - GetRemainingEnergy(), 0.0, joules);
  IncreaseRemainingEnergy(taken);
  DrainedAh() = std::max(0.0, DrainedAh() - taken / (kNominalVoltage * 3600));
  UpdateEnergySource();  // the voltage at the new charge; ns-3's updates stop once it was drained
  CheckThresholds(/*recharged=*/true);
  return taken;
}

void LiIonCell::CheckThresholds(bool recharged) {
  const double remaining = this->*Get(net::LiIonRemainingJ());
  const bool empty = remaining <= cutoff_ * capacity_j_ || GetSupplyVoltage() <= kThresholdVoltage;
  if (!depleted_ && empty) {
    depleted_ = true;
    died_with_j_ = remaining;
    NotifyEnergyDrained();
  } else if (recharged && depleted_ && !empty && remaining >= revives_above_ * capacity_j_ &&
             remaining >= died_with_j_ + 0.05 * capacity_j_) {
    depleted_ = false;
    NotifyEnergyRecharged();
  }
}

}  // namespace sanet::energy
