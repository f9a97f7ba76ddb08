// Stand-in transport without radios: every message reaches its receiver (or, broadcast, every
// other node) after a fixed latency, on the simulation clock. Routing views are empty.
#pragma once

#include <cstddef>
#include <vector>

#include "net/empty_view.h"
#include "net/transport.h"

namespace sanet::net {

class LocalTransport : public Transport {
 public:
  LocalTransport(std::size_t node_count, double latency_s);
  void SetReceiver(Receiver receiver) override { receiver_ = std::move(receiver); }
  void Send(NodeId from, NodeId to, const Bytes& payload) override;
  void Broadcast(NodeId from, const Bytes& payload) override;
  // Without a network every node is a neighbour: a flood is a broadcast.
  void Flood(NodeId from, const Bytes& payload) override;
  NetworkView& View(NodeId) override { return view_; }
  void SwitchOff(NodeId node) override { off_.at(node) = true; }
  void SwitchOn(NodeId node) override { off_.at(node) = false; }
  // A node joins while the run goes (a spawned robot): it takes the next id.
  void AddNode() {
    ++node_count_;
    off_.push_back(false);
  }

 private:
  void Deliver(NodeId receiver, NodeId from, NodeId to, Delivery delivery, const Bytes& payload);

  std::size_t node_count_;
  double latency_;
  Receiver receiver_;
  EmptyView view_{"none"};
  std::vector<bool> off_;
};

}  // namespace sanet::net
