// A battery at a constant voltage, as ns-3's BasicEnergySource models one (energy drawn is the
// models' total current times the voltage, over time), with what that source cannot do: start
// partly charged, be recharged (capped at full), and report depletion at an exact instant. ns-3
// 3.37's BasicEnergySource has one setter for both its capacity and what remains, relates its
// thresholds to that, and notices depletion only at its periodic updates (a second by default).
//
// Depletion: the battery looks at its charge whenever a device model's current changes (each asks
// for an update first) and at a check it schedules for the instant its charge would reach the
// cutoff were it drawn at the most the models can draw (`most_watts`). Such a check is never late,
// so it need not move when the draw changes (a radio's state changes thousands of times a
// second); at each check the next comes closer, and the one at which the charge has reached the
// cutoff finds the node dead when its charge ran out, to the nanojoule, not up to an update
// interval later. Each check brings the charge's margin down by the share of the most the node
// draws: a few dozen checks in its life near that, about 1,200 for a cc2420 mote listening.
//
// Charging: harvesters (energy/charge_harvester.h) give power that ns-3's CalculateTotalCurrent
// nets against the models' draw. While the net is a gain, the battery checks itself when its
// charge would reach the revive level (dead) or full, and takes nothing past full.
#pragma once

#include <ns3/energy-source.h>
#include <ns3/event-id.h>
#include <ns3/nstime.h>

#include <vector>

#include "energy/rechargeable.h"

namespace sanet::energy {

class Battery : public ns3::EnergySource, public Rechargeable {
 public:
  static ns3::TypeId GetTypeId();

  struct Settings {
    double capacity_j = 0;
    double voltage = 0;
    double initial_fraction = 1;
    double cutoff = 0;            // fraction: depleted at or below it
    double revives_above = 0.05;  // fraction: recharged (after a depletion) above it
    double most_watts = 0;        // the most the device models can draw at once
  };
  // Before the run; nothing is drawn until Start (every device model attached by then).
  void Configure(const Settings& settings);
  void Start() override;

  double GetSupplyVoltage() const override { return settings_.voltage; }
  // The capacity: ns-3's fractions are of it.
  double GetInitialEnergy() const override { return settings_.capacity_j; }
  double GetRemainingEnergy() override;
  double GetEnergyFraction() override { return GetRemainingEnergy() / settings_.capacity_j; }
  void UpdateEnergySource() override;

  double Recharge(double joules) override;
  double Take(double joules) override;
  void AddHarvester(ns3::Ptr<ChargeHarvester> harvester) override;
  double harvested_j() override;
  bool depleted() const override { return depleted_; }

 private:
  void DoDispose() override;
  double ChargeAfter(double seconds);
  void Drain();            // what the models drew, less what the harvesters gave, since the last update
  void CheckThresholds();  // depleted or recharged now: tell the models
  void ScheduleNextUpdate();
  void ScheduleWhileCharging(double gain_w);
  void ScheduleCheckIn(double seconds);  // a check no later than that (an earlier one stands)

  Settings settings_;
  double remaining_j_ = 0;
  double harvested_j_ = 0;
  Harvesters harvesters_;
  bool depleted_ = false;
  bool started_ = false;
  ns3::Time last_update_;
  ns3::EventId next_check_;
  ns3::Time next_check_at_;
};

}  // namespace sanet::energy
