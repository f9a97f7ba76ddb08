// What sanet asks of a node's energy source beyond ns-3's EnergySource: a start once its models are
// attached, energy put back (capped at full), and whether it is depleted now. Both of sanet's sources have it
// (energy/battery.h, energy/li_ion_cell.h).
#pragma once

namespace sanet::energy {

class Rechargeable {
 public:
  virtual ~Rechargeable() = default;
  // Once every device model is attached: it draws from now on (a source that starts at its
  // cutoff is depleted at once).
  virtual void Start() = 0;
  // Adds up to `joules`, never past full; returns what it took. The models hear of a revival.
  virtual double Recharge(double joules) = 0;
  virtual bool depleted() const = 0;
};

}  // namespace sanet::energy
