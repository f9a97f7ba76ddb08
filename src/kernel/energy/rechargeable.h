// What sanet asks of a node's energy source beyond ns-3's EnergySource: energy put back (capped at
// full), and whether it is depleted now. Both of sanet's sources have it (energy/battery.h,
// energy/li_ion_cell.h).
#pragma once

namespace sanet::energy {

class Rechargeable {
 public:
  virtual ~Rechargeable() = default;
  // Adds up to `joules`, never past full; returns what it took. The models hear of a revival.
  virtual double Recharge(double joules) = 0;
  virtual bool depleted() const = 0;
};

}  // namespace sanet::energy
