// Messages between controllers. Payloads are bytes; sanet/codec.h writes and reads typed fields.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sanet {

// Small integer id of a node: its index in the scenario's node list (creation order).
using NodeId = std::uint32_t;
constexpr NodeId kBroadcast = 0xFFFFFFFFu;

using Bytes = std::vector<std::uint8_t>;

// How a message travelled: to one node (routed), to the neighbours (one hop), or flooded
// through the whole network.
enum class Delivery { kUnicast, kBroadcast, kFlood };

struct Message {
  Delivery delivery = Delivery::kUnicast;
  NodeId from = 0;
  NodeId to = kBroadcast;    // kBroadcast for a broadcast or a flood
  double time_sent = 0;      // s, simulated (or wall) clock of the sender
  double time_received = 0;  // s
  std::optional<int> hops;   // hops travelled, where the transport knows it
  Bytes payload;
};

}  // namespace sanet
