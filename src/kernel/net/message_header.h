// The header sanet puts before a controller's payload in every UDP datagram: who sent it to
// whom, when, and how (unicast, broadcast, flood, route probe).
#pragma once

#include <ns3/header.h>

#include <cstdint>

#include "net/transport.h"

namespace sanet::net {

class MessageHeader : public ns3::Header {
 public:
  enum Kind : std::uint8_t { kUnicast = 1, kBroadcast = 2, kFlood = 3, kRouteProbe = 4 };

  static ns3::TypeId GetTypeId();
  ns3::TypeId GetInstanceTypeId() const override { return GetTypeId(); }
  std::uint32_t GetSerializedSize() const override { return kSize; }
  void Serialize(ns3::Buffer::Iterator start) const override;
  std::uint32_t Deserialize(ns3::Buffer::Iterator start) override;
  void Print(std::ostream& os) const override;

  Kind kind = kUnicast;
  std::uint32_t origin = 0;
  std::uint32_t destination = 0;
  std::uint32_t sequence = 0;     // per origin
  std::int64_t time_sent_ns = 0;  // simulation time at the origin
  std::uint8_t hops = 0;          // floods: relays so far
  std::uint8_t ttl = 0;           // floods: relays left

 private:
  static constexpr std::uint32_t kMagic = 0x53414E45;  // "SANE"
  static constexpr std::uint32_t kSize = 4 + 1 + 4 + 4 + 4 + 8 + 1 + 1;

 public:
  static constexpr std::uint32_t kBytes = kSize;
};
static_assert(kMostMessageBytes == 65507 - MessageHeader::kBytes, "one UDP datagram over IPv4, less the header");

}  // namespace sanet::net
