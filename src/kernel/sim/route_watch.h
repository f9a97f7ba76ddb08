// Routing-table changes for the run's trace and its observers: each look compares every node's valid routes with
// those of the last look and records the routes that appeared, changed or went away. ns-3's
// routing protocols offer no trace of their tables, so the stepper looks at every recording
// sample (outputs.trajectory_interval).
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "sim/assembly.h"
#include "sim/run_events.h"

namespace sanet::sim {

class RouteWatch {
 public:
  std::vector<RouteChange> Look(double t, Assembly& world);

 private:
  using Table = std::map<NodeId, std::pair<NodeId, int>>;  // destination -> (next hop, hops)
  std::vector<Table> last_;                                // per node
};

}  // namespace sanet::sim
