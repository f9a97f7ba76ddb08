#include "net/tap_port.h"

#include <ns3/boolean.h>
#include <ns3/icmpv4-l4-protocol.h>
#include <ns3/inet-socket-address.h>
#include <ns3/ip-l4-protocol.h>
#include <ns3/ipv4-interface.h>
#include <ns3/ipv4-l3-protocol.h>
#include <ns3/ipv4-raw-socket-factory.h>
#include <ns3/ipv6-interface.h>
#include <ns3/simulator.h>
#include <ns3/tag.h>
#include <ns3/udp-header.h>
#include <ns3/uinteger.h>

namespace sanet::net {
namespace {

constexpr std::uint16_t kIpv4 = 0x0800;
constexpr int kIcmp = 1, kTcp = 6, kUdp = 17;

// When (and from which tap) a real packet entered the simulated network; it travels with the
// packet across nodes, as ns-3's packet tags do.
class TapEntryTag : public ns3::Tag {
 public:
  static ns3::TypeId GetTypeId() {
    static ns3::TypeId tid = ns3::TypeId("sanet::TapEntryTag").SetParent<ns3::Tag>().AddConstructor<TapEntryTag>();
    return tid;
  }
  ns3::TypeId GetInstanceTypeId() const override { return GetTypeId(); }
  std::uint32_t GetSerializedSize() const override { return 13; }
  void Serialize(ns3::TagBuffer b) const override {
    b.WriteU64(static_cast<std::uint64_t>(entered_ns));
    b.WriteU32(origin);
    b.WriteU8(unicast);
  }
  void Deserialize(ns3::TagBuffer b) override {
    entered_ns = static_cast<std::int64_t>(b.ReadU64());
    origin = b.ReadU32();
    unicast = b.ReadU8();
  }
  void Print(std::ostream& os) const override { os << "entered=" << entered_ns << "ns origin=" << origin; }
  std::int64_t entered_ns = 0;
  std::uint32_t origin = 0;
  std::uint8_t unicast = 0;
};

// Stands in for one of ns-3's transport protocols at the node: what the tap's real stack should
// get goes to the tap, the rest to ns-3's own protocol.
class Diverter : public ns3::IpL4Protocol {
 public:
  Diverter(TapPort& port, ns3::Ptr<ns3::IpL4Protocol> inner) : port_(port), inner_(inner) {}
  int GetProtocolNumber() const override { return inner_->GetProtocolNumber(); }
  RxStatus Receive(ns3::Ptr<ns3::Packet> p, const ns3::Ipv4Header& header,
                   ns3::Ptr<ns3::Ipv4Interface> interface) override {
    if (Kept(p)) return inner_->Receive(p, header, interface);
    port_.ToTap(p, header);
    return RX_OK;
  }
  RxStatus Receive(ns3::Ptr<ns3::Packet> p, const ns3::Ipv6Header& header,
                   ns3::Ptr<ns3::Ipv6Interface> interface) override {
    return inner_->Receive(p, header, interface);
  }
  void ReceiveIcmp(ns3::Ipv4Address source, std::uint8_t ttl, std::uint8_t type, std::uint8_t code, std::uint32_t info,
                   ns3::Ipv4Address payload_source, ns3::Ipv4Address payload_destination,
                   const std::uint8_t payload[8]) override {
    inner_->ReceiveIcmp(source, ttl, type, code, info, payload_source, payload_destination, payload);
  }
  void SetDownTarget(DownTargetCallback cb) override { inner_->SetDownTarget(cb); }
  void SetDownTarget6(DownTargetCallback6 cb) override { inner_->SetDownTarget6(cb); }
  DownTargetCallback GetDownTarget() const override { return inner_->GetDownTarget(); }
  DownTargetCallback6 GetDownTarget6() const override { return inner_->GetDownTarget6(); }

 private:
  // TCP belongs to the real stack (ns-3 has no TCP user on the node); UDP only on the ports
  // ns-3 does not serve itself.
  bool Kept(ns3::Ptr<ns3::Packet> p) const {
    if (GetProtocolNumber() != kUdp) return false;
    ns3::UdpHeader udp;
    return p->PeekHeader(udp) == 0 || port_.KeepsUdpPort(udp.GetDestinationPort());
  }
  TapPort& port_;
  ns3::Ptr<ns3::IpL4Protocol> inner_;
};

// ICMP for the node's address (echo, errors about the real stack's packets) goes to the real
// stack; the node keeps sending ICMP errors of its own through this protocol, so it stays an
// ICMP protocol that the IP layer can find.
class IcmpDiverter : public ns3::Icmpv4L4Protocol {
 public:
  explicit IcmpDiverter(TapPort& port) : port_(port) {}
  RxStatus Receive(ns3::Ptr<ns3::Packet> p, const ns3::Ipv4Header& header, ns3::Ptr<ns3::Ipv4Interface>) override {
    port_.ToTap(p, header);
    return RX_OK;
  }
  using ns3::Icmpv4L4Protocol::Receive;

 private:
  TapPort& port_;
};

}  // namespace

TapPort::TapPort(ns3::Ptr<ns3::Node> node, NodeId id, int fd, ns3::Mac48Address tap_mac, Network network,
                 TapLedger& ledger)
    : node_(node), id_(id), tap_mac_(tap_mac), network_(std::move(network)), ledger_(ledger) {
  ledger_[id_];  // a row even if nothing crosses
  device_ = ns3::CreateObject<ns3::FdNetDevice>();
  device_->SetAddress(ns3::Mac48Address::Allocate());
  device_->SetEncapsulationMode(ns3::FdNetDevice::DIX);
  device_->SetFileDescriptor(fd);
  node_->AddDevice(device_);
  // The real stack addresses its frames as it likes (the tap has no ARP): take every one.
  node_->RegisterProtocolHandler(ns3::MakeCallback(&TapPort::FromTap, this), kIpv4, device_, /*promiscuous=*/true);
  auto ip = node_->GetObject<ns3::Ipv4>();
  const auto radio = ip->GetNetDevice(1);  // interface 0 is the loopback
  radio_ = radio;
  node_->RegisterProtocolHandler(ns3::MakeCallback(&TapPort::FromRadio, this), kIpv4, radio_, /*promiscuous=*/false);
  for (ns3::Ptr<ns3::Socket>* socket : {&unicast_, &broadcast_}) {
    *socket = ns3::Socket::CreateSocket(node_, ns3::Ipv4RawSocketFactory::GetTypeId());
    (*socket)->SetAttribute("IpHeaderInclude", ns3::BooleanValue(true));
    (*socket)->ShutdownRecv();
  }
  broadcast_->BindToNetDevice(radio);
  Divert();
}

// ns-3's UDP, TCP and ICMP at this node hand over to the tap what is not theirs.
void TapPort::Divert() {
  auto ip = node_->GetObject<ns3::Ipv4>();
  for (int number : {kUdp, kTcp}) {
    ns3::Ptr<ns3::IpL4Protocol> inner = ip->GetProtocol(number);
    if (!inner) continue;
    ip->Remove(inner);
    ip->Insert(ns3::Create<Diverter>(*this, inner));
  }
  if (ns3::Ptr<ns3::IpL4Protocol> icmp = ip->GetProtocol(kIcmp)) ip->Remove(icmp);
  auto icmp = ns3::CreateObject<IcmpDiverter>(*this);
  icmp->SetNode(node_);
  icmp->SetDownTarget(ns3::MakeCallback(&ns3::Ipv4::Send, ip));
  ip->Insert(icmp);
}

void TapPort::FromTap(ns3::Ptr<ns3::NetDevice>, ns3::Ptr<const ns3::Packet> packet, std::uint16_t protocol,
                      const ns3::Address&, const ns3::Address&, ns3::NetDevice::PacketType) {
  if (protocol != kIpv4) return;
  ns3::Ptr<ns3::Packet> p = packet->Copy();
  ns3::Ipv4Header header;
  if (p->PeekHeader(header) == 0) return;
  auto ip = node_->GetObject<ns3::Ipv4>();
  const ns3::Ipv4Address to = header.GetDestination();
  // Only what the node itself could have sent: its own source address.
  if (ip->GetInterfaceForAddress(header.GetSource()) < 0) return;
  if (to.IsMulticast()) return SendMulticast(p, header);
  const bool broadcast = to.IsBroadcast() || to.IsSubnetDirectedBroadcast(ip->GetAddress(1, 0).GetMask());
  // Unicasts to another real stack can be counted as lost or arrived; those to a mote cannot.
  const std::optional<NodeId> addressee = network_.node_at(to);
  const bool to_a_tap = !broadcast && addressee && ledger_.count(*addressee) > 0;
  TapCounts& mine = ledger_[id_];
  ++mine.packets_sent;
  mine.bytes_sent += p->GetSize();
  mine.unicast_sent += to_a_tap;
  TapEntryTag tag;
  tag.entered_ns = ns3::Simulator::Now().GetNanoSeconds();
  tag.origin = id_;
  tag.unicast = to_a_tap;
  p->AddPacketTag(tag);
  if (network_.entered) {
    ns3::Ptr<ns3::Packet> payload = p->Copy();
    payload->RemoveHeader(header);
    network_.entered(id_, header, payload);
  }
  (broadcast ? broadcast_ : unicast_)->SendTo(p, 0, ns3::InetSocketAddress(to, 0));
}

void TapPort::SendMulticast(ns3::Ptr<ns3::Packet> packet, const ns3::Ipv4Header& header) {
  TapCounts& mine = ledger_[id_];
  ++mine.packets_sent;
  mine.bytes_sent += packet->GetSize();
  TapEntryTag tag;
  tag.entered_ns = ns3::Simulator::Now().GetNanoSeconds();
  tag.origin = id_;
  tag.unicast = false;
  packet->AddPacketTag(tag);
  if (network_.entered) {
    ns3::Ptr<ns3::Packet> payload = packet->Copy();
    ns3::Ipv4Header stripped;
    payload->RemoveHeader(stripped);
    network_.entered(id_, header, payload);
  }
  radio_->Send(packet, ns3::Mac48Address::GetMulticast(header.GetDestination()), kIpv4);
}

// A multicast frame another node's real stack sent: to this node's real stack. (ns-3's IP layer
// drops it too: no route, since no routing protocol here routes multicast.)
void TapPort::FromRadio(ns3::Ptr<ns3::NetDevice>, ns3::Ptr<const ns3::Packet> packet, std::uint16_t protocol,
                        const ns3::Address&, const ns3::Address&, ns3::NetDevice::PacketType) {
  if (protocol != kIpv4) return;
  ns3::Ptr<ns3::Packet> p = packet->Copy();
  ns3::Ipv4Header header;
  if (p->RemoveHeader(header) == 0 || !header.GetDestination().IsMulticast()) return;
  ToTap(p, header);
}

void TapPort::ToTap(ns3::Ptr<ns3::Packet> packet, ns3::Ipv4Header header) {
  TapCounts& mine = ledger_[id_];
  TapEntryTag tag;
  if (packet->RemovePacketTag(tag)) {
    mine.delays.push_back((ns3::Simulator::Now().GetNanoSeconds() - tag.entered_ns) * 1e-9);
    if (tag.unicast) ++ledger_[tag.origin].unicast_arrived;
  }
  header.EnableChecksum();  // the real stack checks it
  packet->AddHeader(header);
  ++mine.packets_received;
  mine.bytes_received += packet->GetSize();
  device_->Send(packet, tap_mac_, kIpv4);
}

}  // namespace sanet::net
