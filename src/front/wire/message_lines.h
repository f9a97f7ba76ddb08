// sanet's extension of the robot protocol for messages between a client's robot and the nodes
// that live in the server (motes, robots without an agent): the client sends with SEND and the
// server hands over what reached the robot's ns-3 node with MSG. Payloads travel as hex.
//
//   SEND {Delivery unicast} {To m3} {Data 0a1b...}       (or {Delivery broadcast|flood}, no To)
//   MSG {From m3} {Delivery unicast} {TimeSent 12.000100} {TimeReceived 12.004300} {Hops 2} {Data ...}
//
// Controllers' typed events travel the same way:
//   TRANSITION {From searching} {To travelling} {Why route found}
//   METRIC {Name hop_time} {Value 3.25}
// and an agent's record of what other agents sent it over UDP:
//   RECV {From f1} {Delivery unicast} {TimeSent 12.000100} {TimeReceived 12.001300} {Bytes 41} {Hops 1}
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/delivery.h"
#include "sanet/message.h"
#include "wire/protocol.h"

namespace sanet::wire {

// The largest RECV {Bytes n} (a UDP datagram's payload) and {Hops h} a line may give.
constexpr std::uint64_t kMostDatagramBytes = 65507, kMostHops = 1000;

std::string ToHex(const Bytes& bytes);
std::optional<Bytes> FromHex(const std::string& text);  // nullopt unless pairs of hex digits

// MSG line for a message that reached `message.to`'s node, with names for node ids.
ProtocolMessage MsgLine(const Message& message, const std::string& from_name);

// RECV line: an agent tells the server of a message another agent's UDP datagram brought it,
// for messages.csv (the server never sees those).
ProtocolMessage RecvLine(const Message& message, const std::string& from_name);
// The server's side: the message (payload empty, `bytes` set) or nullopt with `error`.
struct ReceivedReport {
  Message message;
  std::size_t bytes = 0;
};
std::optional<ReceivedReport> ParseRecvLine(const ProtocolMessage& line, const std::optional<NodeId>& from, NodeId to,
                                            std::string* error);

// Reads a MSG line back into a message (the agent side); `from` resolved by name. Says what is
// wrong in `error` otherwise.
std::optional<Message> ParseMsgLine(const ProtocolMessage& line, const std::optional<NodeId>& from, NodeId to,
                                    std::string* error);

}  // namespace sanet::wire
