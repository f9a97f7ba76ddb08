// A real IP stack joined to one node of the simulated network through a tap device (an agent's
// network namespace). Frames the real stack sends out of its tap reach an ns-3 FdNetDevice on
// the node; their IP packets enter the node's IP layer as if the node had sent them (a raw
// socket with the header included), so the node's routing protocol carries them over the
// simulated radio. Packets that reach the node for its own address go out of the tap instead of
// to ns-3's transport protocols: ICMP, TCP and every UDP port but the simulated network's own
// (the routing protocol's, and sanet's message port), which stay in ns-3. The real stack uses
// the node's own address, so routing finds it as it finds any node.
#pragma once

#include <ns3/fd-net-device.h>
#include <ns3/ipv4-header.h>
#include <ns3/mac48-address.h>
#include <ns3/node.h>
#include <ns3/socket.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <set>

#include "net/network_traces.h"

namespace sanet::net {

class TapPort {
 public:
  // What the port needs of the network it joins.
  struct Network {
    std::set<std::uint16_t> kept_udp_ports;                          // UDP ports ns-3 itself serves
    std::function<std::optional<NodeId>(ns3::Ipv4Address)> node_at;  // the node with this address
    // A real packet entered the network at `node` (IP header apart), for the packet traces.
    std::function<void(NodeId node, const ns3::Ipv4Header&, ns3::Ptr<const ns3::Packet>)> entered;
  };
  // `fd`: an open tap (IFF_TAP | IFF_NO_PI); `tap_mac`: the address of the tap interface in the
  // real stack, to which frames are sent. `ledger` holds every tap's counts.
  TapPort(ns3::Ptr<ns3::Node> node, NodeId id, int fd, ns3::Mac48Address tap_mac, Network network, TapLedger& ledger);
  TapPort(const TapPort&) = delete;
  TapPort& operator=(const TapPort&) = delete;

  // Out of the tap: the packet (IP header included) as the node received it for itself.
  void ToTap(ns3::Ptr<ns3::Packet> packet, ns3::Ipv4Header header);
  bool KeepsUdpPort(std::uint16_t port) const { return network_.kept_udp_ports.count(port) > 0; }

 private:
  void FromTap(ns3::Ptr<ns3::NetDevice> device, ns3::Ptr<const ns3::Packet> packet, std::uint16_t protocol,
               const ns3::Address& from, const ns3::Address& to, ns3::NetDevice::PacketType type);
  // IPv4 multicast: one 802.11 group frame from this node's radio, relayed by no one (no routing
  // protocol of sanet's routes multicast), taken by every node in range that has a tap.
  void SendMulticast(ns3::Ptr<ns3::Packet> packet, const ns3::Ipv4Header& header);
  void FromRadio(ns3::Ptr<ns3::NetDevice> device, ns3::Ptr<const ns3::Packet> packet, std::uint16_t protocol,
                 const ns3::Address& from, const ns3::Address& to, ns3::NetDevice::PacketType type);
  void Divert();

  ns3::Ptr<ns3::Node> node_;
  NodeId id_;
  ns3::Ptr<ns3::FdNetDevice> device_;
  ns3::Mac48Address tap_mac_;
  Network network_;
  ns3::Ptr<ns3::Socket> unicast_, broadcast_;  // raw IP, header included; the second bound to the radio
  ns3::Ptr<ns3::NetDevice> radio_;
  TapLedger& ledger_;
};

}  // namespace sanet::net
