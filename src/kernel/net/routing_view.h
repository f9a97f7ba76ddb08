// A node's view of its own network layer, read from ns-3's routing protocol objects.
//
// What each protocol offers:
//   aodv  routing table (next hop, hops, valid, expiry), neighbours, invalidation, requests
//   dsdv  routing table (next hop, hops, valid; no expiry), neighbours, requests
//   olsr  routing table (next hop, hops; all valid, no expiry), neighbours, requests
//   dsr   requests only: ns-3 keeps DSR's route cache inside the protocol with no reader
//   none  nothing: one-hop delivery, no table
// Neighbours are the destinations one hop away with a valid route, and on a node with an 802.15.4
// radio (which no routing protocol serves) the nodes it heard in the last 10 s.
#pragma once

#include <ns3/node.h>
#include <ns3/ptr.h>

#include <functional>

#include "net/address_book.h"
#include "net/network_spec.h"
#include "sanet/node.h"

namespace sanet::net {

class RoutingView : public NetworkView {
 public:
  // `probe` sends a route probe from this node towards a destination.
  // `heard`: the nodes its 802.15.4 radio heard lately (none without one), neighbours too.
  RoutingView(Routing routing, ns3::Ptr<ns3::Node> node, const AddressBook& book, std::function<void(NodeId)> probe,
              std::function<std::vector<NodeId>()> heard = {})
      : routing_(routing), node_(node), book_(book), probe_(std::move(probe)), heard_(std::move(heard)) {}

  std::string Protocol() const override { return RoutingName(routing_); }
  std::vector<RouteEntry> RoutingTable() const override;
  std::vector<NodeId> Neighbours() const override;
  bool InvalidateRoute(NodeId destination) override;
  void RequestRoute(NodeId destination) override { probe_(destination); }

  // Whether a packet to `destination` would leave now without a route discovery.
  bool HasValidRoute(NodeId destination) const;

 private:
  Routing routing_;
  ns3::Ptr<ns3::Node> node_;
  const AddressBook& book_;
  std::function<void(NodeId)> probe_;
  std::function<std::vector<NodeId>()> heard_;
};

}  // namespace sanet::net
