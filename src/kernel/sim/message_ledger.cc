#include "sim/message_ledger.h"

#include <algorithm>
#include <cmath>

namespace sanet::sim {

MessageLedger::MessageLedger(std::unique_ptr<net::Transport> inner, std::function<double()> now, double horizon)
    : inner_(std::move(inner)), now_(std::move(now)), horizon_(horizon) {
  inner_->SetReceiver([this](NodeId to, const Message& m) { Arrived(to, m); });
}

void MessageLedger::Send(NodeId from, NodeId to, const Bytes& payload) {
  Sent(from, to, Delivery::kUnicast, payload);
  inner_->Send(from, to, payload);
}

void MessageLedger::Broadcast(NodeId from, const Bytes& payload) {
  Sent(from, std::nullopt, Delivery::kBroadcast, payload);
  inner_->Broadcast(from, payload);
}

void MessageLedger::Flood(NodeId from, const Bytes& payload) {
  Sent(from, std::nullopt, Delivery::kFlood, payload);
  inner_->Flood(from, payload);
}

void MessageLedger::Sent(NodeId from, std::optional<NodeId> to, Delivery delivery, const Bytes& payload) {
  if (!watched_) return;
  Expire();
  in_flight_.push_back({from, to, delivery, now_(), payload.size()});
}

void MessageLedger::Arrived(NodeId to, const Message& m) {
  if (watched_) {
    const auto same = [&](const MessageInFlight& f) {
      return f.from == m.from && f.delivery == m.delivery && std::abs(f.time_sent - m.time_sent) < 1e-9 &&
             (m.delivery != Delivery::kUnicast || f.to == to);
    };
    const auto it = std::find_if(in_flight_.begin(), in_flight_.end(), same);
    if (it != in_flight_.end()) in_flight_.erase(it);
  }
  if (receiver_) receiver_(to, m);
}

void MessageLedger::Expire() const {
  const double now = now_();
  while (!in_flight_.empty() && in_flight_.front().time_sent < now - horizon_) in_flight_.pop_front();
}

std::vector<MessageInFlight> MessageLedger::InFlight() const {
  Expire();
  return {in_flight_.begin(), in_flight_.end()};
}

}  // namespace sanet::sim
