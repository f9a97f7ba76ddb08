#include "net/routing_view.h"

#include <ns3/aodv-routing-protocol.h>
#include <ns3/dsdv-routing-protocol.h>
#include <ns3/ipv4.h>
#include <ns3/olsr-routing-protocol.h>

#include <algorithm>
#include <limits>

#include "net/private_access.h"

namespace sanet::net {

// ns-3 3.37 gives no reader for the AODV and DSDV tables (only a text dump) and no way to
// invalidate an AODV route from outside: reach the tables themselves.
SANET_PRIVATE_MEMBER(AodvTable, ns3::aodv::RoutingProtocol, ns3::aodv::RoutingTable, m_routingTable);
using AodvEntryMap = std::map<ns3::Ipv4Address, ns3::aodv::RoutingTableEntry>;
SANET_PRIVATE_MEMBER(AodvEntries, ns3::aodv::RoutingTable, AodvEntryMap, m_ipv4AddressEntry);
SANET_PRIVATE_MEMBER(DsdvTable, ns3::dsdv::RoutingProtocol, ns3::dsdv::RoutingTable, m_routingTable);

namespace {

constexpr double kNoExpiry = std::numeric_limits<double>::infinity();

template <typename Protocol>
ns3::Ptr<Protocol> ProtocolOf(const ns3::Ptr<ns3::Node>& node) {
  return ns3::DynamicCast<Protocol>(node->GetObject<ns3::Ipv4>()->GetRoutingProtocol());
}

ns3::aodv::RoutingTable& AodvTableOf(const ns3::Ptr<ns3::Node>& node) {
  return (*ProtocolOf<ns3::aodv::RoutingProtocol>(node)).*Get(AodvTable());
}

}  // namespace

std::vector<RouteEntry> RoutingView::RoutingTable() const {
  std::vector<RouteEntry> out;
  auto add = [&](ns3::Ipv4Address destination, ns3::Ipv4Address next_hop, int hops, bool valid, double expires_in) {
    const auto d = book_.Find(destination), n = book_.Find(next_hop);
    if (d && n) out.push_back({*d, *n, hops, valid, expires_in});  // skips broadcast and loopback
  };
  switch (routing_) {
    case Routing::kAodv: {
      const auto& entries = AodvTableOf(node_).*Get(AodvEntries());
      for (const auto& [address, e] : entries) {
        // Not GetSeconds(): an expired route's lifetime is negative, and ns-3's int64x64 conversion
        // shifts a negative value left (undefined behaviour, which UBSan reports).
        const double left = static_cast<double>(e.GetLifeTime().GetNanoSeconds()) / 1e9;
        add(address, e.GetNextHop(), e.GetHop(), e.GetFlag() == ns3::aodv::VALID && left > 0, left);
      }
      break;
    }
    case Routing::kDsdv: {
      std::map<ns3::Ipv4Address, ns3::dsdv::RoutingTableEntry> entries;
      ((*ProtocolOf<ns3::dsdv::RoutingProtocol>(node_)).*Get(DsdvTable())).GetListOfAllRoutes(entries);
      for (const auto& [address, e] : entries)
        add(address, e.GetNextHop(), e.GetHop(), e.GetFlag() == ns3::dsdv::VALID, kNoExpiry);
      break;
    }
    case Routing::kOlsr:
      for (const auto& e : ProtocolOf<ns3::olsr::RoutingProtocol>(node_)->GetRoutingTableEntries())
        add(e.destAddr, e.nextAddr, e.distance, true, kNoExpiry);
      break;
    case Routing::kDsr:
    case Routing::kNone:
      break;
  }
  std::sort(out.begin(), out.end(),
            [](const RouteEntry& a, const RouteEntry& b) { return a.destination < b.destination; });
  return out;
}

std::vector<NodeId> RoutingView::Neighbours() const {
  std::vector<NodeId> out;
  for (const RouteEntry& e : RoutingTable())
    if (e.valid && e.hops == 1 && e.next_hop == e.destination) out.push_back(e.destination);
  if (!heard_) return out;
  for (NodeId n : heard_()) out.push_back(n);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool RoutingView::InvalidateRoute(NodeId destination) {
  if (routing_ != Routing::kAodv) return false;
  ns3::aodv::RoutingTable& table = AodvTableOf(node_);
  ns3::aodv::RoutingTableEntry entry;
  if (table.LookupValidRoute(book_.Of(destination), entry))
    table.InvalidateRoutesWithDst({{book_.Of(destination), entry.GetSeqNo()}});
  return true;
}

bool RoutingView::HasValidRoute(NodeId destination) const {
  if (routing_ == Routing::kAodv) {
    ns3::aodv::RoutingTableEntry entry;
    return AodvTableOf(node_).LookupValidRoute(book_.Of(destination), entry);
  }
  for (const RouteEntry& e : RoutingTable())
    if (e.destination == destination) return e.valid;
  return false;
}

}  // namespace sanet::net
