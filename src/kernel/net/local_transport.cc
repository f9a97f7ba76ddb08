#include "net/local_transport.h"

#include <ns3/simulator.h>

namespace sanet::net {

LocalTransport::LocalTransport(std::size_t node_count, double latency_s)
    : node_count_(node_count), latency_(latency_s), off_(node_count, false) {}

void LocalTransport::Deliver(NodeId receiver, NodeId from, NodeId to, Delivery delivery, const Bytes& payload) {
  if (off_[from] || off_[receiver]) return;
  Message m;
  m.delivery = delivery;
  m.from = from;
  m.to = to;
  m.time_sent = ns3::Simulator::Now().GetSeconds();
  m.hops = 1;
  m.payload = payload;
  ns3::Simulator::Schedule(ns3::Seconds(latency_), [this, receiver, m]() mutable {
    m.time_received = ns3::Simulator::Now().GetSeconds();
    if (receiver_ && !off_[receiver]) receiver_(receiver, m);
  });
}

void LocalTransport::Send(NodeId from, NodeId to, const Bytes& payload) {
  if (to >= node_count_ || to == from) return;
  Deliver(to, from, to, Delivery::kUnicast, payload);
}

void LocalTransport::Broadcast(NodeId from, const Bytes& payload) {
  for (NodeId receiver = 0; receiver < node_count_; ++receiver)
    if (receiver != from) Deliver(receiver, from, kBroadcast, Delivery::kBroadcast, payload);
}

void LocalTransport::Flood(NodeId from, const Bytes& payload) {
  for (NodeId receiver = 0; receiver < node_count_; ++receiver)
    if (receiver != from) Deliver(receiver, from, kBroadcast, Delivery::kFlood, payload);
}

}  // namespace sanet::net
