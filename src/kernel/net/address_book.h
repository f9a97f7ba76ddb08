// Node ids and IPv4 addresses: node i has 10.0.0.0 + i + 1 in a /16, so up to 65534 nodes.
#pragma once

#include <ns3/ipv4-address.h>

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
  std::size_t size() const { return count_; }
  void Add() { ++count_; }  // the next node joins (a spawned robot)

 private:
  static constexpr std::uint32_t kBase = 0x0A000000;  // 10.0.0.0
  std::size_t count_;
};

}  // namespace sanet::net
