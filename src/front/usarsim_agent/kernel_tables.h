// What this host's kernel knows of the way to other robots, read over rtnetlink (Linux), and
// that knowledge as a routing view in node ids: the network view of an agent whose traffic to
// the other robots crosses real networks (namespaces on a bridge, robots' own computers).
//
// A node's address is where its agent listens for the others (the run's peer addresses). An
// address that is no node's (a router, an access point, the default route's gateway) maps to
// nothing: a route through it is left out, as is a neighbour entry for it. An address that more
// than one node holds (loopback, where every agent is 127.0.0.1) is no single node's either, so
// on one machine the tables are empty.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sanet/node.h"

namespace sanet::usarsim_agent {

using Ipv4 = std::uint32_t;  // network byte order, as in in_addr

// The route the kernel takes to one address (`ip route get`): through a gateway, or direct.
struct KernelRoute {
  Ipv4 destination = 0;
  std::optional<Ipv4> gateway;
};

// An entry of the kernel's neighbour (ARP) table in a state that knows the neighbour's link
// address (reachable, stale, delay, probe, permanent).
struct KernelNeighbour {
  Ipv4 address = 0;
};

// The kernel's route to `destination`, or nothing when it has none (unreachable). Throws
// std::runtime_error when rtnetlink cannot be used at all.
std::optional<KernelRoute> KernelRouteTo(Ipv4 destination);
std::vector<KernelNeighbour> KernelNeighbours();

// The kernel's tables in node ids, for `self`, given every node's address (nothing for a node
// whose agent's address is unknown).
struct KernelTables {
  std::vector<RouteEntry> routes;
  std::vector<NodeId> neighbours;
};
KernelTables MapToNodes(NodeId self, const std::vector<std::optional<Ipv4>>& addresses,
                        const std::vector<KernelRoute>& routes, const std::vector<KernelNeighbour>& neighbours);

// Reads the kernel's route to every other node's address and its neighbour table, mapped.
KernelTables ReadKernelTables(NodeId self, const std::vector<std::optional<Ipv4>>& addresses);

}  // namespace sanet::usarsim_agent
