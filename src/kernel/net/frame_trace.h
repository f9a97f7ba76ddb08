// Every radio frame each node's PHY sends and receives (ns-3's monitor sniffer traces), named by
// what it carries, for the run's trace: data, routing (AODV/OLSR/DSDV), arp, broadcast, ack,
// control or management. Senders and receivers are found by their MAC addresses.
#pragma once

#include <ns3/mac48-address.h>
#include <ns3/packet.h>
#include <ns3/wifi-net-device.h>

#include <map>

#include "net/network_traces.h"

namespace sanet::net {

// What a frame's payload of `ethertype` carries: arp, routing (AODV/OLSR/DSDV over UDP), else
// broadcast or data. Reads (and removes) the IP header from `body`, a copy.
const char* PayloadKind(std::uint16_t ethertype, ns3::Ptr<ns3::Packet> body, bool broadcast);

class FrameTrace {
 public:
  explicit FrameTrace(FrameObserver observer) : observer_(std::move(observer)) {}
  void Attach(NodeId node, ns3::Ptr<ns3::WifiNetDevice> device);

 private:
  void Seen(NodeId node, bool sent, ns3::Ptr<const ns3::Packet> mpdu);
  std::optional<NodeId> NodeAt(ns3::Mac48Address address) const;

  FrameObserver observer_;
  std::map<ns3::Mac48Address, NodeId> nodes_;
};

}  // namespace sanet::net
