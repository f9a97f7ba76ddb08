#include "net/packet_trace.h"

#include <ns3/aodv-packet.h>
#include <ns3/node.h>
#include <ns3/simulator.h>
#include <ns3/udp-header.h>
#include <ns3/wifi-mac.h>
#include <ns3/wifi-net-device.h>

#include <cstdio>

#include "net/network_spec.h"

namespace sanet::net {
namespace {

constexpr std::uint8_t kIcmpv6Protocol = 58;

const char* EventName(int e) {
  static const char* names[] = {"sent", "received", "forwarded", "dropped"};
  return names[e];
}

const char* DropName(ns3::Ipv4L3Protocol::DropReason reason) {
  switch (reason) {
    case ns3::Ipv4L3Protocol::DROP_TTL_EXPIRED:
      return "ttl_expired";
    case ns3::Ipv4L3Protocol::DROP_NO_ROUTE:
      return "no_route";
    case ns3::Ipv4L3Protocol::DROP_BAD_CHECKSUM:
      return "bad_checksum";
    case ns3::Ipv4L3Protocol::DROP_INTERFACE_DOWN:
      return "interface_down";
    case ns3::Ipv4L3Protocol::DROP_ROUTE_ERROR:
      return "route_error";
    case ns3::Ipv4L3Protocol::DROP_FRAGMENT_TIMEOUT:
      return "fragment_timeout";
    case ns3::Ipv4L3Protocol::DROP_DUPLICATE:
      return "duplicate";
  }
  return "other";
}

}  // namespace

PacketTrace::PacketTrace(const NetworkSpec& spec, const AddressBook& book, std::vector<std::string> names)
    : spec_(spec), book_(book), names_(std::move(names)), counts_(names_.size()) {}

void PacketTrace::Open(trace::ResultsFolder& folder) {
  logs_.clear();
  if (!spec_.packet_log) return;
  folder_ = &folder;
  for (const std::string& name : names_)
    logs_.push_back(&folder.Csv("packets/" + name + ".csv", "time,event,protocol,bytes,peer,reason", 64 * 1024));
}

void PacketTrace::AddNode(const std::string& name) {
  names_.push_back(name);
  counts_.emplace_back();
  if (folder_)
    logs_.push_back(&folder_->Csv("packets/" + name + ".csv", "time,event,protocol,bytes,peer,reason", 64 * 1024));
}

void PacketTrace::Attach(NodeId node, ns3::Ptr<ns3::Node> n) {
  auto ip = n->GetObject<ns3::Ipv4L3Protocol>();
  ip->TraceConnectWithoutContext("SendOutgoing",
                                 ns3::Callback<void, const ns3::Ipv4Header&, ns3::Ptr<const ns3::Packet>, uint32_t>(
                                     [this, node](const ns3::Ipv4Header& h, ns3::Ptr<const ns3::Packet> p, uint32_t) {
                                       Record(node, Event::kSent, h, p);
                                     }));
  ip->TraceConnectWithoutContext("UnicastForward",
                                 ns3::Callback<void, const ns3::Ipv4Header&, ns3::Ptr<const ns3::Packet>, uint32_t>(
                                     [this, node](const ns3::Ipv4Header& h, ns3::Ptr<const ns3::Packet> p, uint32_t) {
                                       // AODV sends a packet that waited for a route back through the
                                       // forwarding path of its own node: that is not relaying.
                                       if (book_.Find(h.GetSource()) != node) Record(node, Event::kForwarded, h, p);
                                     }));
  ip->TraceConnectWithoutContext("LocalDeliver",
                                 ns3::Callback<void, const ns3::Ipv4Header&, ns3::Ptr<const ns3::Packet>, uint32_t>(
                                     [this, node](const ns3::Ipv4Header& h, ns3::Ptr<const ns3::Packet> p, uint32_t) {
                                       Record(node, Event::kReceived, h, p);
                                       if (spec_.routing == Routing::kAodv) CheckRouteReply(node, h, p);
                                     }));
  ip->TraceConnectWithoutContext(
      "Drop",
      ns3::Callback<void, const ns3::Ipv4Header&, ns3::Ptr<const ns3::Packet>, ns3::Ipv4L3Protocol::DropReason,
                    ns3::Ptr<ns3::Ipv4>, uint32_t>(
          [this, node](const ns3::Ipv4Header& h, ns3::Ptr<const ns3::Packet> p, ns3::Ipv4L3Protocol::DropReason reason,
                       ns3::Ptr<ns3::Ipv4>, uint32_t) { Record(node, Event::kDropped, h, p, DropName(reason)); }));
  for (std::uint32_t i = 0; i < n->GetNDevices(); ++i) {
    auto wifi = ns3::DynamicCast<ns3::WifiNetDevice>(n->GetDevice(i));
    if (!wifi) continue;
    wifi->GetMac()->TraceConnectWithoutContext(
        "MacTxDrop", ns3::Callback<void, ns3::Ptr<const ns3::Packet>>([this, node](ns3::Ptr<const ns3::Packet> p) {
          ++counts_[node].dropped;
          if (!logs_.empty())
            logs_[node]->Row(std::to_string(ns3::Simulator::Now().GetSeconds()) + ",dropped,mac," +
                             std::to_string(p->GetSize()) + ",,refused_by_mac");
        }));
  }
}

namespace {

const char* Drop6Name(ns3::Ipv6L3Protocol::DropReason reason) {
  switch (reason) {
    case ns3::Ipv6L3Protocol::DROP_TTL_EXPIRED:
      return "ttl_expired";
    case ns3::Ipv6L3Protocol::DROP_NO_ROUTE:
      return "no_route";
    case ns3::Ipv6L3Protocol::DROP_INTERFACE_DOWN:
      return "interface_down";
    case ns3::Ipv6L3Protocol::DROP_FRAGMENT_TIMEOUT:
      return "fragment_timeout";
    default:
      return "other";
  }
}

}  // namespace

// An 802.15.4 node's IPv6 layer, as Attach does its IPv4 one (no forwarding: no IPv6 routing).
void PacketTrace::Attach6(NodeId node, ns3::Ptr<ns3::Node> n) {
  using Sent = ns3::Callback<void, const ns3::Ipv6Header&, ns3::Ptr<const ns3::Packet>, uint32_t>;
  auto ip = n->GetObject<ns3::Ipv6L3Protocol>();
  ip->TraceConnectWithoutContext("SendOutgoing",
                                 Sent([this, node](const ns3::Ipv6Header& h, ns3::Ptr<const ns3::Packet> p, uint32_t) {
                                   Record6(node, Event::kSent, h, p);
                                 }));
  ip->TraceConnectWithoutContext("LocalDeliver",
                                 Sent([this, node](const ns3::Ipv6Header& h, ns3::Ptr<const ns3::Packet> p, uint32_t) {
                                   Record6(node, Event::kReceived, h, p);
                                 }));
  ip->TraceConnectWithoutContext(
      "Drop",
      ns3::Callback<void, const ns3::Ipv6Header&, ns3::Ptr<const ns3::Packet>, ns3::Ipv6L3Protocol::DropReason,
                    ns3::Ptr<ns3::Ipv6>, uint32_t>(
          [this, node](const ns3::Ipv6Header& h, ns3::Ptr<const ns3::Packet> p, ns3::Ipv6L3Protocol::DropReason reason,
                       ns3::Ptr<ns3::Ipv6>, uint32_t) { Record6(node, Event::kDropped, h, p, Drop6Name(reason)); }));
}

std::string PacketTrace::Protocol(const ns3::Ipv4Header& ip, ns3::Ptr<const ns3::Packet> packet) const {
  if (ip.GetProtocol() != kUdpProtocol) return ip.GetProtocol() == 48 ? "dsr" : "ip";
  ns3::UdpHeader udp;
  if (packet->PeekHeader(udp) == 0) return "udp";
  const std::uint16_t port = udp.GetDestinationPort();
  if (port == spec_.port) return "sanet";
  if (port == kAodvPort) return "aodv";
  if (port == kOlsrPort) return "olsr";
  if (port == kDsdvPort) return "dsdv";
  return "udp";
}

std::string PacketTrace::Peer(ns3::Ipv4Address address) const {
  if (auto id = book_.Find(address)) return names_[*id];
  if (address.IsBroadcast() || address.IsSubnetDirectedBroadcast(ns3::Ipv4Mask(AddressBook::kMask))) return "*";
  std::ostringstream s;
  address.Print(s);
  return s.str();
}

void PacketTrace::Record(NodeId node, Event event, const ns3::Ipv4Header& ip, ns3::Ptr<const ns3::Packet> packet,
                         const char* why) {
  Count(node, event);
  if (logs_.empty()) return;
  const ns3::Ipv4Address peer = event == Event::kReceived ? ip.GetSource() : ip.GetDestination();
  Log(node, event, Protocol(ip, packet), packet->GetSize(), Peer(peer), why);
}

void PacketTrace::Record6(NodeId node, Event event, const ns3::Ipv6Header& ip, ns3::Ptr<const ns3::Packet> packet,
                          const char* why) {
  Count(node, event);
  if (logs_.empty()) return;
  const ns3::Ipv6Address peer = event == Event::kReceived ? ip.GetSource() : ip.GetDestination();
  std::string protocol = "ipv6";
  if (ip.GetNextHeader() == kIcmpv6Protocol) protocol = "icmpv6";
  ns3::UdpHeader udp;
  if (ip.GetNextHeader() == kUdpProtocol)
    protocol = packet->PeekHeader(udp) && udp.GetDestinationPort() == spec_.port ? "sanet" : "udp";
  std::string name;
  if (auto id = book_.Find6(peer)) {
    name = names_[*id];
  } else if (peer.IsMulticast()) {
    name = "*";
  } else {
    std::ostringstream s;
    peer.Print(s);
    name = s.str();
  }
  Log(node, event, protocol, packet->GetSize(), name, why);
}

void PacketTrace::MacGaveUp(NodeId node, std::uint32_t bytes) {
  Count(node, Event::kDropped);
  if (!logs_.empty()) Log(node, Event::kDropped, "mac", bytes, "", "mac_gave_up");
}

void PacketTrace::Unreachable(NodeId node, NodeId to, std::size_t bytes) {
  Count(node, Event::kDropped);
  if (!logs_.empty())
    Log(node, Event::kDropped, "sanet", static_cast<std::uint32_t>(bytes), to < names_.size() ? names_[to] : "",
        "no_shared_radio");
}

void PacketTrace::Log(NodeId node, Event event, const std::string& protocol, std::uint32_t bytes,
                      const std::string& peer, const char* why) {
  char time[32];
  std::snprintf(time, sizeof time, "%.6f", ns3::Simulator::Now().GetSeconds());
  logs_[node]->Row(std::string(time) + "," + EventName(static_cast<int>(event)) + "," + protocol + "," +
                   std::to_string(bytes) + "," + peer + "," + why);
}

void PacketTrace::Count(NodeId node, Event event) {
  PacketCounts& c = counts_[node];
  switch (event) {
    case Event::kSent:
      ++c.sent;
      break;
    case Event::kReceived:
      ++c.received;
      break;
    case Event::kForwarded:
      ++c.forwarded;
      break;
    case Event::kDropped:
      ++c.dropped;
      break;
  }
}

void PacketTrace::RouteNeeded(NodeId node, NodeId destination, double now) {
  auto it = pending_.find({node, destination});
  // AODV gives up on a discovery after its retries (about 8 s at ns-3's defaults): one still
  // open after kGiveUp stays unanswered in routes.csv, and a new one starts.
  constexpr double kGiveUp = 10;
  if (it != pending_.end() && now - discoveries_[it->second].started < kGiveUp) return;
  pending_[{node, destination}] = discoveries_.size();
  discoveries_.push_back({node, destination, now, std::nullopt});
}

// A route reply addressed to the node that asked ends that node's discovery.
void PacketTrace::CheckRouteReply(NodeId node, const ns3::Ipv4Header& ip, ns3::Ptr<const ns3::Packet> packet) {
  if (ip.GetProtocol() != kUdpProtocol || pending_.empty()) return;
  ns3::Ptr<ns3::Packet> p = packet->Copy();
  ns3::UdpHeader udp;
  p->RemoveHeader(udp);
  if (udp.GetDestinationPort() != kAodvPort) return;
  ns3::aodv::TypeHeader type;
  p->RemoveHeader(type);
  if (!type.IsValid() || type.Get() != ns3::aodv::AODVTYPE_RREP) return;
  ns3::aodv::RrepHeader reply;
  p->RemoveHeader(reply);
  const auto origin = book_.Find(reply.GetOrigin());
  const auto destination = book_.Find(reply.GetDst());
  if (!origin || *origin != node || !destination) return;
  auto it = pending_.find({node, *destination});
  if (it == pending_.end()) return;
  discoveries_[it->second].established = ns3::Simulator::Now().GetSeconds();
  pending_.erase(it);
}

}  // namespace sanet::net
