// Messages between controllers. Payloads are bytes; TypedMessage helps to define small
// fixed records without hand-packing.
#pragma once

#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace sanet {

// Small integer id of a node: its index in the scenario's node list (creation order).
using NodeId = std::uint32_t;
constexpr NodeId kBroadcast = 0xFFFFFFFFu;

using Bytes = std::vector<std::uint8_t>;

struct Message {
  NodeId from = 0;
  NodeId to = kBroadcast;        // kBroadcast for a one-hop broadcast
  double time_sent = 0;          // s, simulated (or wall) clock of the sender
  double time_received = 0;      // s
  std::optional<int> hops;       // hops travelled, where the transport knows it
  Bytes payload;
};

// Packs a trivially copyable struct into bytes and back, checking the size on the way in.
// Both ends must be built for the same architecture (the same struct layout).
template <typename T>
Bytes Pack(const T& value) {
  static_assert(std::is_trivially_copyable_v<T>, "Pack needs a trivially copyable type");
  Bytes out(sizeof(T));
  std::memcpy(out.data(), &value, sizeof(T));
  return out;
}

template <typename T>
std::optional<T> Unpack(const Bytes& bytes) {
  static_assert(std::is_trivially_copyable_v<T>, "Unpack needs a trivially copyable type");
  if (bytes.size() != sizeof(T)) return std::nullopt;
  T value;
  std::memcpy(&value, bytes.data(), sizeof(T));
  return value;
}

}  // namespace sanet
