// The robot protocol, compatible with USARSim's text protocol: one message per line,
// `TYPE {Key Value} {Key Value} ...`. Commands and keys are case-insensitive; inside braces the
// first word is the key and the rest the value; braces may touch. Lines end with CR LF (we
// accept CR LF, LF CR, LF or CR). docs/protocol.md lists every message.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sanet::wire {

// The version of sanet's own extensions to the protocol (the SANET line, docs/protocol.md): a
// server and an agent work together only when theirs are equal. 2: clock exchanges, scenario and
// plugin from the server, peers' addresses (1: before the version was exchanged). 3: END and
// FINISHED at the end of a run, RADIO, named sensor instances on SEN lines.
constexpr int kSanetProtocol = 3;

struct ProtocolMessage {
  explicit ProtocolMessage(std::string message_type = "") : type(std::move(message_type)) {}
  std::string type;                                         // upper case
  std::vector<std::pair<std::string, std::string>> fields;  // key as written, value trimmed

  ProtocolMessage& Add(std::string key, std::string value) {
    fields.emplace_back(std::move(key), std::move(value));
    return *this;
  }
  ProtocolMessage& Add(std::string key, double value);
  ProtocolMessage& Add(std::string key, const std::vector<double>& values);
  // First field whose key matches (case-insensitive).
  const std::string* Get(std::string_view key) const;
  std::optional<double> Number(std::string_view key) const;
  // A whole number from 0 to `most`; nothing for a fraction, a negative or a larger number.
  std::optional<std::uint64_t> Count(std::string_view key, std::uint64_t most) const;
  // Comma- or space-separated numbers.
  std::optional<std::vector<double>> Numbers(std::string_view key) const;
};

// Parses one line (without its end). On failure returns nullopt and says why in `error`.
std::optional<ProtocolMessage> ParseLine(std::string_view line, std::string* error);
// "TYPE {Key Value} ...\r\n"
std::string FormatLine(const ProtocolMessage& message);
std::string FormatNumber(double value);   // 4 decimals: metres, radians, seconds
std::string FormatPrecise(double value);  // 6 decimals

// Splits a byte stream into lines; refuses lines longer than a limit. Linear in the bytes it is
// given: lines are taken from a moving start and the buffer is compacted only when most of it
// has been taken, and a partial line is never scanned twice.
class LineReader {
 public:
  explicit LineReader(std::size_t max_line) : max_line_(max_line) {}
  void Append(std::string_view bytes);
  // The next complete line, if any. Sets `too_long` when the pending line exceeds the limit.
  std::optional<std::string> Next(bool* too_long);
  // Bytes appended and not yet taken as lines.
  std::size_t Pending() const { return buffer_.size() - start_; }

 private:
  std::size_t max_line_;
  std::string buffer_;
  std::size_t start_ = 0;    // where the next line begins
  std::size_t scanned_ = 0;  // bytes from start_ known to hold no line end
  char partner_ = 0;         // the other half of a CR LF (LF CR) whose first half ended the data
};

}  // namespace sanet::wire
