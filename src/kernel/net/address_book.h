// Node ids and addresses: node i has 10.0.0.0 + i + 1 in a /16 on 802.11, so up to 65534 nodes;
// on 802.15.4 the short address i + 1, and the IPv6 address fd00::ff:fe00:(i + 1) made from it
// (RFC 6282's interface identifier of a short address), in the prefix fd00::/64.
#pragma once

#include <ns3/ipv4-address.h>
#include <ns3/ipv6-address.h>
#include <ns3/mac16-address.h>
#include <ns3/mac48-address.h>

#include <optional>

#include "sanet/message.h"

namespace sanet::net {

class AddressBook {
 public:
  explicit AddressBook(std::size_t node_count) : count_(node_count) {}
  static constexpr const char* kNetwork = "10.0.0.0";
  static constexpr const char* kMask = "255.255.0.0";

  ns3::Ipv4Address Of(NodeId id) const { return ns3::Ipv4Address(kBase + id + 1); }
  std::optional<NodeId> Find(ns3::Ipv4Address address) const {
    const std::uint32_t a = address.Get();
    if (a <= kBase || a > kBase + count_) return std::nullopt;
    return static_cast<NodeId>(a - kBase - 1);
  }
  static constexpr const char* kPrefix6 = "fd00::";
  static constexpr std::uint16_t kPanId = 0x5a4e;
  static ns3::Mac16Address ShortOf(NodeId id) {
    const std::uint16_t a = static_cast<std::uint16_t>(id + 1);
    const std::uint8_t bytes[2] = {static_cast<std::uint8_t>(a >> 8), static_cast<std::uint8_t>(a & 0xff)};
    ns3::Mac16Address out;
    out.CopyFrom(bytes);
    return out;
  }
  // The Mac48 form ns-3's LrWpanNetDevice gives IPv6 for a short address (02:00:00:00:hi:lo).
  static ns3::Mac48Address Pseudo48Of(NodeId id) {
    const std::uint16_t a = static_cast<std::uint16_t>(id + 1);
    const std::uint8_t bytes[6] = {
        0x02, 0, 0, 0, static_cast<std::uint8_t>(a >> 8), static_cast<std::uint8_t>(a & 0xff)};
    ns3::Mac48Address out;
    out.CopyFrom(bytes);
    return out;
  }
  static ns3::Ipv6Address Of6(NodeId id) {
    return ns3::Ipv6Address::MakeAutoconfiguredAddress(ShortOf(id), ns3::Ipv6Address(kPrefix6));
  }
  std::optional<NodeId> Find6(ns3::Ipv6Address address) const {
    std::uint8_t b[16];
    address.GetBytes(b);
    const std::uint8_t prefix[16] = {0xfd, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xff, 0xfe, 0, 0, 0};
    for (int i = 0; i < 14; ++i)
      if (b[i] != prefix[i] && !(i < 2 && address.IsLinkLocal())) return std::nullopt;
    const std::uint32_t a = (b[14] << 8) | b[15];
    if (a == 0 || a > count_) return std::nullopt;
    return static_cast<NodeId>(a - 1);
  }
  std::size_t size() const { return count_; }
  void Add() { ++count_; }  // the next node joins (a spawned robot)

 private:
  static constexpr std::uint32_t kBase = 0x0A000000;  // 10.0.0.0
  std::size_t count_;
};

}  // namespace sanet::net
