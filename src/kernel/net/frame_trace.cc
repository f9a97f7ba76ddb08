#include "net/frame_trace.h"

#include <ns3/ipv4-header.h>
#include <ns3/llc-snap-header.h>
#include <ns3/simulator.h>
#include <ns3/udp-header.h>
#include <ns3/wifi-mac-header.h>
#include <ns3/wifi-phy.h>

#include "net/network_spec.h"

namespace sanet::net {
namespace {

constexpr std::uint16_t kArp = 0x0806, kIpv4 = 0x0800;

// What a data frame carries, from its LLC/SNAP, IP and UDP headers.
const char* DataKind(const ns3::WifiMacHeader& mac, ns3::Ptr<ns3::Packet> body) {
  ns3::LlcSnapHeader llc;
  if (body->RemoveHeader(llc) == 0) return "data";
  return PayloadKind(llc.GetType(), body, mac.GetAddr1().IsBroadcast());
}

}  // namespace

const char* PayloadKind(std::uint16_t ethertype, ns3::Ptr<ns3::Packet> body, bool broadcast) {
  if (ethertype == kArp) return "arp";
  ns3::Ipv4Header ip;
  if (ethertype == kIpv4 && body->RemoveHeader(ip) != 0 && ip.GetProtocol() == kUdpProtocol) {
    ns3::UdpHeader udp;
    if (body->PeekHeader(udp) != 0) {
      const std::uint16_t port = udp.GetDestinationPort();
      if (port == kAodvPort || port == kOlsrPort || port == kDsdvPort) return "routing";
    }
  }
  return broadcast ? "broadcast" : "data";
}

void FrameTrace::Attach(NodeId node, ns3::Ptr<ns3::WifiNetDevice> device) {
  nodes_[ns3::Mac48Address::ConvertFrom(device->GetAddress())] = node;
  auto phy = device->GetPhy();
  phy->TraceConnectWithoutContext(
      "MonitorSnifferTx",
      ns3::Callback<void, ns3::Ptr<const ns3::Packet>, uint16_t, ns3::WifiTxVector, ns3::MpduInfo, uint16_t>(
          [this, node](ns3::Ptr<const ns3::Packet> p, uint16_t, ns3::WifiTxVector, ns3::MpduInfo, uint16_t) {
            Seen(node, true, p);
          }));
  phy->TraceConnectWithoutContext(
      "MonitorSnifferRx",
      ns3::Callback<void, ns3::Ptr<const ns3::Packet>, uint16_t, ns3::WifiTxVector, ns3::MpduInfo, ns3::SignalNoiseDbm,
                    uint16_t>([this, node](ns3::Ptr<const ns3::Packet> p, uint16_t, ns3::WifiTxVector, ns3::MpduInfo,
                                           ns3::SignalNoiseDbm, uint16_t) { Seen(node, false, p); }));
}

std::optional<NodeId> FrameTrace::NodeAt(ns3::Mac48Address address) const {
  const auto it = nodes_.find(address);
  return it == nodes_.end() ? std::nullopt : std::optional<NodeId>(it->second);
}

void FrameTrace::Seen(NodeId node, bool sent, ns3::Ptr<const ns3::Packet> mpdu) {
  FrameEvent e;
  e.t = ns3::Simulator::Now().GetSeconds();
  e.node = node;
  e.sent = sent;
  e.bytes = mpdu->GetSize();
  ns3::Ptr<ns3::Packet> body = mpdu->Copy();
  ns3::WifiMacHeader mac;
  if (body->RemoveHeader(mac) == 0) return;
  if (mac.IsAck())
    e.kind = "ack";
  else if (mac.IsCtl())
    e.kind = "control";
  else if (mac.IsMgt())
    e.kind = "management";
  else
    e.kind = DataKind(mac, body);
  // A frame sent goes to its receiver address; one received comes from its transmitter (an ACK
  // names no transmitter).
  if (sent && !mac.GetAddr1().IsBroadcast()) e.peer = NodeAt(mac.GetAddr1());
  if (!sent && !mac.IsAck() && !mac.IsCts()) e.peer = NodeAt(mac.GetAddr2());
  observer_(e);
}

}  // namespace sanet::net
