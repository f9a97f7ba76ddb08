// What the network did, per node: IP packets sent (originated, including routing traffic),
// received (delivered locally, broadcasts included), forwarded and dropped (by IP: no route,
// TTL, ...; by the MAC: retries exhausted), controller messages sent and received; and every
// AODV route discovery (from the first packet that needed the route to the route reply).
#pragma once

#include <ns3/ipv4-header.h>
#include <ns3/ipv4-l3-protocol.h>
#include <ns3/ipv6-header.h>
#include <ns3/ipv6-l3-protocol.h>
#include <ns3/packet.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "net/address_book.h"
#include "net/network_spec.h"
#include "net/network_traces.h"
#include "trace/results_folder.h"

namespace sanet::net {

class PacketTrace {
 public:
  PacketTrace(const NetworkSpec& spec, const AddressBook& book, std::vector<std::string> names);

  // Connects to the node's IP layer and MAC (before the run).
  void Attach(NodeId node, ns3::Ptr<ns3::Node> ns3_node);
  // Connects to the IPv6 layer of a node with an 802.15.4 radio.
  void Attach6(NodeId node, ns3::Ptr<ns3::Node> ns3_node);
  // An 802.15.4 MAC gave a frame up (no acknowledgement after its retries, or a busy channel):
  // `bytes` is the frame's, MAC header included.
  void MacGaveUp(NodeId node, std::uint32_t bytes);
  // A message from `node` to `to`, which shares no radio with it, goes nowhere.
  void Unreachable(NodeId node, NodeId to, std::size_t bytes);
  // Opens the per-node packet logs (packets/<node>.csv) in the results folder.
  void Open(trace::ResultsFolder& folder);
  // A node joins while the run goes (a spawned robot): counts, and its log if logs are open.
  void AddNode(const std::string& name);

  void MessageSent(NodeId node) { ++counts_[node].messages_sent; }
  void MessageReceived(NodeId node) { ++counts_[node].messages_received; }
  // A real program's packet entered the network at `node` (through its tap): sent, as the node's own.
  void ExternalSent(NodeId node, const ns3::Ipv4Header& ip, ns3::Ptr<const ns3::Packet> packet) {
    Record(node, Event::kSent, ip, packet);
  }
  // A packet to `destination` is waiting for a route (AODV): a discovery starts unless one is on.
  void RouteNeeded(NodeId node, NodeId destination, double now);

  const std::vector<PacketCounts>& counts() const { return counts_; }
  const std::vector<Discovery>& discoveries() const { return discoveries_; }

 private:
  enum class Event { kSent, kReceived, kForwarded, kDropped };
  void Record(NodeId node, Event event, const ns3::Ipv4Header& ip, ns3::Ptr<const ns3::Packet> packet,
              const char* why = "");
  void Record6(NodeId node, Event event, const ns3::Ipv6Header& ip, ns3::Ptr<const ns3::Packet> packet,
               const char* why = "");
  void Count(NodeId node, Event event);
  void Log(NodeId node, Event event, const std::string& protocol, std::uint32_t bytes, const std::string& peer,
           const char* why);
  void CheckRouteReply(NodeId node, const ns3::Ipv4Header& ip, ns3::Ptr<const ns3::Packet> packet);
  std::string Protocol(const ns3::Ipv4Header& ip, ns3::Ptr<const ns3::Packet> packet) const;
  std::string Peer(ns3::Ipv4Address address) const;

  const NetworkSpec& spec_;
  const AddressBook& book_;
  std::vector<std::string> names_;
  std::vector<PacketCounts> counts_;
  std::vector<trace::CsvSink*> logs_;  // owned by the results folder
  trace::ResultsFolder* folder_ = nullptr;
  std::vector<Discovery> discoveries_;
  std::map<std::pair<NodeId, NodeId>, std::size_t> pending_;  // (node, destination) -> discovery
};

}  // namespace sanet::net
