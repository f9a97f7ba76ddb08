// The run's chargers (docs/energy.md#chargers): the world's, which charge every node with a
// battery whose reference point is inside their radius, and the wireless chargers robots carry,
// which power the motes around them by their efficiency model (energy::WirelessCharger). Every
// kInterval of simulated time, an ns-3 event, it measures the distances and sets each node's
// harvester; the power is constant in between.
#pragma once

#include <utility>
#include <vector>

#include "sim/assembly.h"

namespace sanet::sim {

class Chargers {
 public:
  static constexpr double kInterval = 0.1;     // s
  static constexpr double kTopUpBelow = 0.99;  // of a full mote's charge: a wireless charger's
  explicit Chargers(Assembly& world) : world_(world) {}
  // Starts the updates if the run has a charger (or a robot joined with one); again is harmless.
  void Start();

 private:
  void Update();
  std::vector<double> WorldChargersGive() const;  // W per node
  // What the wireless chargers give the motes (added to `given`); each robot radiates while a
  // mote it reaches is not full.
  void WirelessChargersGive(std::vector<double>& given);
  std::vector<std::pair<NodeId, double>> SharesOf(NodeId robot);
  bool NeedsCharge(NodeId mote, const energy::NodeEnergy& energy);
  bool Alive(NodeId id) const;

  Assembly& world_;
  bool started_ = false;
  std::vector<char> topping_up_;  // per mote: charged since it last fell below kTopUpBelow, not full yet
};

}  // namespace sanet::sim
