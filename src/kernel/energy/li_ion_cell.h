// A lithium-ion battery whose voltage follows a discharge curve: ns-3's LiIonEnergySource
// (Tremblay, Dessaint and Dekkiche's model, "A generic battery model for the dynamic simulation of
// hybrid electric vehicles", IEEE VPPC 2007) with ns-3's default cell (4.05 V full, 3.6 V nominal,
// 2.45 Ah), its capacities, typical current and internal resistance scaled to the scenario's
// capacity as cells in parallel. What ns-3's source does not do, sanet adds here:
// - start partly charged (the drained capacity that sets the voltage, too);
// - recharge, never past full, giving back drained capacity so that the voltage recovers (ns-3's
//   IncreaseRemainingEnergy changes the charge only);
// - depletion when the charge reaches the cutoff or the voltage falls to the cell's threshold
//   (3.3 V: the curve falls steeply, and without end, past it), and revival once recharged
//   above the revive level and by 5 % of its capacity above the charge it died with (without its
//   load a cell's voltage recovers by itself), which ns-3's source never reports.
// Like ns-3's source it looks at its charge at its periodic updates (every second) and whenever
// a device model changes state, so a death may come up to a second after the threshold.
#pragma once

#include <ns3/li-ion-energy-source.h>

#include <vector>

#include "energy/rechargeable.h"

namespace sanet::energy {

class LiIonCell : public ns3::LiIonEnergySource, public Rechargeable {
 public:
  static ns3::TypeId GetTypeId();
  static constexpr double kDefaultCellJ = 2.45 * 3.6 * 3600;  // ns-3's default cell, J
  static constexpr double kThresholdVoltage = 3.3;            // ns-3's default, V

  // Before the run: the attributes for a pack of `capacity_j`, and the charge at the start.
  void Configure(double capacity_j, double initial_fraction, double cutoff, double revives_above);
  void Start() override;

  void UpdateEnergySource() override;
  // What remains now, without an update (a read changes nothing; ns-3's own read updates, and
  // does nothing once the simulator has stopped).
  double GetRemainingEnergy() override;
  double Recharge(double joules) override;
  double Take(double joules) override;
  void AddHarvester(ns3::Ptr<ChargeHarvester> harvester) override;
  double harvested_j() override;
  bool depleted() const override { return depleted_; }

 private:
  // Depleted now, or (after a recharge only: without its load a cell's voltage recovers by
  // itself) revived.
  void CheckThresholds(bool recharged = false);
  double& DrainedAh();
  double ChargeAfter(double seconds);
  // ns-3's update nets the harvest like a negative current: this keeps the charge at or below
  // full and counts what the harvesters put in.
  void KeepBelowFull(double harvested_w, double seconds);

  double capacity_j_ = 0, cutoff_ = 0, revives_above_ = 0.05;
  double died_with_j_ = 0;  // the charge it died with: a pack dead of its voltage needs more
  double harvested_j_ = 0;
  Harvesters harvesters_;
  bool depleted_ = false, started_ = false;
};

}  // namespace sanet::energy
