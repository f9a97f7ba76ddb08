// The transport every simulated node talks to: it passes everything to the run's real transport
// (the ns-3 network or the local stand-in) and, once someone watches the run, keeps the
// application messages in flight for the world's snapshots. A unicast is in flight until it
// reaches its addressee; a broadcast or flood until its first receiver has it. Either stops
// counting `horizon` seconds after it was sent (lost on the way, or never answered by anyone).
#pragma once

#include <deque>
#include <memory>

#include "net/transport.h"
#include "sim/snapshot.h"

namespace sanet::sim {

class MessageLedger : public net::Transport {
 public:
  MessageLedger(std::unique_ptr<net::Transport> inner, std::function<double()> now, double horizon = 2.0);

  void Watch() { watched_ = true; }  // from the first observer on
  std::vector<MessageInFlight> InFlight() const;
  net::Transport& inner() { return *inner_; }

  void SetReceiver(Receiver receiver) override { receiver_ = std::move(receiver); }
  void Send(NodeId from, NodeId to, const Bytes& payload) override;
  void Broadcast(NodeId from, const Bytes& payload) override;
  void Flood(NodeId from, const Bytes& payload) override;
  NetworkView& View(NodeId node) override { return inner_->View(node); }
  void SwitchOff(NodeId node) override { inner_->SwitchOff(node); }
  void SwitchOn(NodeId node) override { inner_->SwitchOn(node); }
  bool SetSleep(NodeId node, bool asleep) override { return inner_->SetSleep(node, asleep); }
  void Open(trace::ResultsFolder& folder) override { inner_->Open(folder); }
  void Close() override { inner_->Close(); }
  std::optional<net::NetworkTraces> Traces() const override { return inner_->Traces(); }
  void Moved(const std::vector<NodeId>& nodes) override { inner_->Moved(nodes); }
  void ObserveFrames(net::FrameObserver observer) override { inner_->ObserveFrames(std::move(observer)); }

 private:
  void Sent(NodeId from, std::optional<NodeId> to, Delivery delivery, const Bytes& payload);
  void Arrived(NodeId to, const Message& message);
  void Expire() const;

  std::unique_ptr<net::Transport> inner_;
  std::function<double()> now_;
  double horizon_;
  Receiver receiver_;
  bool watched_ = false;
  mutable std::deque<MessageInFlight> in_flight_;  // in sending order
};

}  // namespace sanet::sim
