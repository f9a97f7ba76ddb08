// Power put into a node's battery from outside it, through ns-3's EnergyHarvester interface: a
// charger in the world the robot stands in, or a robot's wireless charger near a mote
// (docs/energy.md#chargers). ns-3's BasicEnergyHarvester draws its power from a random variable
// on a fixed period; this one's power is set by whoever knows it (sim, each time a charger's
// distance changes), and the source nets it against its models' draw (EnergySource's
// CalculateTotalCurrent), never past full (energy/battery.h).
#pragma once

#include <ns3/energy-harvester.h>

namespace sanet::energy {

class ChargeHarvester : public ns3::EnergyHarvester {
 public:
  static ns3::TypeId GetTypeId();
  // The source it gives to, which settles what was drawn and harvested at the old power before
  // the new one applies. Not ns-3's SetEnergySource: that Ptr, with the source's Ptr to its
  // harvesters, would be a cycle that keeps both alive.
  void Attach(ns3::EnergySource* source) { source_ = source; }
  void SetPower(double watts);

 private:
  double DoGetPower() const override { return watts_; }
  double watts_ = 0;
  ns3::EnergySource* source_ = nullptr;
};

}  // namespace sanet::energy
