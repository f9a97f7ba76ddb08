#include "wire/message_lines.h"

#include <cstdio>

namespace sanet::wire {
namespace {

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::string ToHex(const Bytes& bytes) {
  static const char* kDigits = "0123456789abcdef";
  std::string out;
  out.reserve(bytes.size() * 2);
  for (std::uint8_t b : bytes) out += kDigits[b >> 4], out += kDigits[b & 15];
  return out;
}

std::optional<Bytes> FromHex(const std::string& text) {
  if (text.size() % 2) return std::nullopt;
  Bytes out;
  out.reserve(text.size() / 2);
  for (std::size_t i = 0; i < text.size(); i += 2) {
    const int hi = HexDigit(text[i]), lo = HexDigit(text[i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    out.push_back(static_cast<std::uint8_t>(hi * 16 + lo));
  }
  return out;
}

ProtocolMessage RecvLine(const Message& m, const std::string& from_name) {
  ProtocolMessage line("RECV");
  line.Add("From", from_name).Add("Delivery", DeliveryName(m.delivery));
  line.Add("TimeSent", FormatPrecise(m.time_sent)).Add("TimeReceived", FormatPrecise(m.time_received));
  line.Add("Bytes", std::to_string(m.payload.size()));
  if (m.hops) line.Add("Hops", std::to_string(*m.hops));
  return line;
}

std::optional<ReceivedReport> ParseRecvLine(const ProtocolMessage& line, const std::optional<NodeId>& from, NodeId to,
                                            std::string* error) {
  const std::string* delivery = line.Get("Delivery");
  const auto kind = delivery ? ParseDelivery(*delivery) : std::nullopt;
  const auto sent = line.Number("TimeSent"), received = line.Number("TimeReceived");
  const auto bytes = line.Count("Bytes", kMostDatagramBytes);
  const auto hops = line.Count("Hops", kMostHops);
  if (!from || !kind || !sent || !received || !bytes || (line.Get("Hops") && !hops)) {
    *error = "RECV needs {From node} {Delivery unicast|broadcast|flood} {TimeSent} {TimeReceived} {Bytes n} (n up to " +
             std::to_string(kMostDatagramBytes) + "), and may give {Hops h} (h up to " + std::to_string(kMostHops) +
             ")";
    return std::nullopt;
  }
  ReceivedReport r;
  const Delivery delivery_kind = kind.value_or(Delivery::kUnicast);
  r.message.from = *from, r.message.to = delivery_kind == Delivery::kUnicast ? to : kBroadcast;
  r.message.delivery = delivery_kind;
  r.message.time_sent = *sent, r.message.time_received = *received;
  if (hops) r.message.hops = static_cast<int>(*hops);
  r.bytes = static_cast<std::size_t>(*bytes);
  r.message.payload.assign(r.bytes, 0);  // its size is what the results keep
  return r;
}

ProtocolMessage MsgLine(const Message& m, const std::string& from_name) {
  ProtocolMessage line("MSG");
  line.Add("From", from_name).Add("Delivery", DeliveryName(m.delivery));
  line.Add("TimeSent", FormatPrecise(m.time_sent)).Add("TimeReceived", FormatPrecise(m.time_received));
  if (m.hops) line.Add("Hops", std::to_string(*m.hops));
  line.Add("Data", ToHex(m.payload));
  return line;
}

std::optional<Message> ParseMsgLine(const ProtocolMessage& line, const std::optional<NodeId>& from, NodeId to,
                                    std::string* error) {
  const std::string* delivery = line.Get("Delivery");
  const std::string* data = line.Get("Data");
  const auto sent = line.Number("TimeSent"), received = line.Number("TimeReceived");
  const auto hops = line.Count("Hops", kMostHops);
  Message m;
  std::optional<Bytes> payload = data ? FromHex(*data) : std::nullopt;
  std::optional<Delivery> kind = delivery ? ParseDelivery(*delivery) : std::nullopt;
  if (!from || !kind || !payload || !sent || !received || (line.Get("Hops") && !hops)) {
    *error =
        "MSG needs {From node} {Delivery unicast|broadcast|flood} {TimeSent} {TimeReceived} {Data hex}, and may "
        "give {Hops h} (h up to " +
        std::to_string(kMostHops) + ")";
    return std::nullopt;
  }
  m.from = *from, m.to = *kind == Delivery::kUnicast ? to : kBroadcast, m.delivery = *kind,
  m.payload = std::move(*payload);
  m.time_sent = *sent, m.time_received = *received;
  if (hops) m.hops = static_cast<int>(*hops);
  return m;
}

}  // namespace sanet::wire
