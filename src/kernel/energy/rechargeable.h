// What sanet asks of a node's energy source beyond ns-3's EnergySource: a start once its models are
// attached, energy put back (capped at full) at once or by harvesters, energy taken at once, and
// whether it is depleted now. Both of sanet's sources have it (energy/battery.h,
// energy/li_ion_cell.h).
#pragma once

#include <ns3/energy-source.h>
#include <ns3/ptr.h>

#include <algorithm>
#include <vector>

#include "energy/charge_harvester.h"

namespace sanet::energy {

// The harvesters of a source: ns-3's source nets their power against its models' draw
// (CalculateTotalCurrent) but keeps its list private, so each of sanet's sources keeps this one
// too, to count what they gave.
class Harvesters {
 public:
  void Add(ns3::EnergySource& source, ns3::Ptr<ChargeHarvester> harvester) {
    source.ConnectEnergyHarvester(harvester);
    harvester->Attach(&source);
    list_.push_back(ns3::PeekPointer(harvester));
  }
  double Watts() const {
    double watts = 0;
    for (const ChargeHarvester* h : list_) watts += h->GetPower();
    return watts;
  }
  // What they put in over `seconds` at their power now, when `lost_j` would have gone past full.
  double Gave(double seconds, double lost_j) const { return std::max(0.0, Watts() * seconds - lost_j); }

 private:
  std::vector<const ChargeHarvester*> list_;  // the source holds them
};

class Rechargeable {
 public:
  virtual ~Rechargeable() = default;
  // Once every device model is attached: it draws from now on (a source that starts at its
  // cutoff is depleted at once).
  virtual void Start() = 0;
  // Adds up to `joules`, never past full; returns what it took. The models hear of a revival.
  virtual double Recharge(double joules) = 0;
  // Takes `joules` at once (a wheel's work in a physics step, a sensor's reading); returns what it took.
  virtual double Take(double joules) = 0;
  // A harvester whose power the source nets against its models' draw (ns-3's
  // ConnectEnergyHarvester), never charging past full.
  virtual void AddHarvester(ns3::Ptr<ChargeHarvester> harvester) = 0;
  // What the harvesters put in up to now (less what a full battery could not take).
  virtual double harvested_j() = 0;
  virtual bool depleted() const = 0;
};

}  // namespace sanet::energy
