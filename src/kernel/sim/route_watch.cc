#include "sim/route_watch.h"

namespace sanet::sim {

std::vector<RouteChange> RouteWatch::Look(double t, Assembly& world) {
  std::vector<RouteChange> changes;
  last_.resize(world.size());
  for (NodeId node = 0; node < world.size(); ++node) {
    Table now;
    for (const RouteEntry& r : world.transport().View(node).RoutingTable())
      if (r.valid && r.destination != node) now[r.destination] = {r.next_hop, r.hops};
    Table& before = last_[node];
    for (const auto& [destination, route] : now) {
      const auto it = before.find(destination);
      if (it == before.end() || it->second != route)
        changes.push_back({t, node, destination, route.first, route.second});
    }
    for (const auto& [destination, route] : before)
      if (!now.count(destination)) changes.push_back({t, node, destination, std::nullopt, 0});
    before = std::move(now);
  }
  return changes;
}

}  // namespace sanet::sim
