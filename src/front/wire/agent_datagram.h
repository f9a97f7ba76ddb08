// The datagrams agents send each other over UDP (robot to robot, not through the server). Each
// carries its sender, receiver, kind, send time and a sequence number, and ends with an
// HMAC-SHA256 over all of it under the run's key, which the server gives every client that
// claims a robot (the KEY line, docs/protocol.md). A receiver drops datagrams whose MAC fails
// (forged, altered, from another run) and those whose sequence number it has seen or that are
// too old (replayed), so that a process that can reach an agent's port cannot speak for a robot.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "sanet/message.h"

namespace sanet::wire {

class DatagramKey {
 public:
  static DatagramKey Random();  // 256 bits from the operating system's generator
  static std::optional<DatagramKey> FromHex(const std::string& hex);
  std::string Hex() const;
  const std::array<std::uint8_t, 32>& bytes() const { return bytes_; }

 private:
  std::array<std::uint8_t, 32> bytes_{};
};

struct AgentDatagram {
  static constexpr std::uint32_t kToAll = 0xFFFFFFFF;  // `to` of a broadcast
  enum Kind : std::uint8_t { kUnicast = 1, kBroadcast = 2 };
  NodeId from = 0;
  std::uint32_t to = 0;
  Kind kind = kUnicast;
  std::uint64_t sequence = 0;  // per sender, from 1
  double time_sent = 0;        // s, the sender's clock
  Bytes payload;
};

constexpr std::size_t kDatagramHeader = 27, kDatagramMac = 32;

Bytes SealDatagram(const AgentDatagram& datagram, const DatagramKey& key);
// `bytes` followed by their MAC under `key` (SealDatagram's last step).
Bytes WithMac(Bytes bytes, const DatagramKey& key);
// The datagram if it is well formed and its MAC holds; otherwise nothing, and why.
std::optional<AgentDatagram> OpenDatagram(const std::uint8_t* data, std::size_t size, const DatagramKey& key,
                                          std::string* why);

// Which sequence numbers of one sender have been taken: the highest, and a window of the 64
// below it (as IPsec's anti-replay window), so that datagrams the network reorders still count
// once and a replayed or very old one does not.
class ReplayWindow {
 public:
  bool Take(std::uint64_t sequence);  // false: seen before, or older than the window

 private:
  std::uint64_t highest_ = 0;
  std::uint64_t seen_ = 0;  // bit i: highest_ - i taken
};

}  // namespace sanet::wire
