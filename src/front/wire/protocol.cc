#include "wire/protocol.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sanet::wire {
namespace {

bool SameWord(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return std::tolower(x) == std::tolower(y); });
}

std::string_view Trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::optional<double> ToNumber(std::string_view text) {
  std::string s(Trim(text));
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (*end != '\0' || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

std::string FormatNumber(double value) {
  char s[40];
  // Values that round to zero print as 0.0000, never -0.0000 (a frame change negates zeros).
  std::snprintf(s, sizeof s, "%.4f", std::fabs(value) < 5e-5 ? 0.0 : value);
  return s;
}

std::string FormatPrecise(double value) {
  char s[40];
  std::snprintf(s, sizeof s, "%.6f", value);
  return s;
}

ProtocolMessage& ProtocolMessage::Add(std::string key, double value) {
  return Add(std::move(key), FormatNumber(value));
}

ProtocolMessage& ProtocolMessage::Add(std::string key, const std::vector<double>& values) {
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? "," : "") + FormatNumber(values[i]);
  return Add(std::move(key), text);
}

const std::string* ProtocolMessage::Get(std::string_view key) const {
  for (const auto& [k, v] : fields)
    if (SameWord(k, key)) return &v;
  return nullptr;
}

std::optional<double> ProtocolMessage::Number(std::string_view key) const {
  const std::string* v = Get(key);
  return v ? ToNumber(*v) : std::nullopt;
}

std::optional<std::uint64_t> ProtocolMessage::Count(std::string_view key, std::uint64_t most) const {
  const auto n = Number(key);
  // Compared as doubles before any conversion: a double beyond the integer's range converts to
  // nothing defined.
  if (!n || *n < 0 || *n > static_cast<double>(most) || *n != std::floor(*n)) return std::nullopt;
  return static_cast<std::uint64_t>(*n);
}

std::optional<std::vector<double>> ProtocolMessage::Numbers(std::string_view key) const {
  const std::string* v = Get(key);
  if (!v) return std::nullopt;
  std::vector<double> out;
  std::string item;
  for (char c : *v + ",") {
    if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
      if (!item.empty()) {
        const auto n = ToNumber(item);
        if (!n) return std::nullopt;
        out.push_back(*n);
      }
      item.clear();
    } else {
      item += c;
    }
  }
  return out;
}

std::optional<ProtocolMessage> ParseLine(std::string_view line, std::string* error) {
  line = Trim(line);
  std::size_t i = 0;
  while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])) && line[i] != '{') ++i;
  if (i == 0) {
    *error = line.empty() ? "empty line" : "a message starts with its type";
    return std::nullopt;
  }
  ProtocolMessage m;
  for (char c : line.substr(0, i)) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') {
      *error = "a message type is a word";
      return std::nullopt;
    }
    m.type += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  while (i < line.size()) {
    if (std::isspace(static_cast<unsigned char>(line[i]))) {
      ++i;
      continue;
    }
    if (line[i] != '{') {
      *error = "expected an opening brace at column " + std::to_string(i + 1);
      return std::nullopt;
    }
    const std::size_t close = line.find('}', i);
    const std::size_t nested = line.find('{', i + 1);
    if (close == std::string_view::npos || (nested != std::string_view::npos && nested < close)) {
      *error = "the brace opened at column " + std::to_string(i + 1) +
               " is not closed before another opens or the line ends";
      return std::nullopt;
    }
    const std::string_view inside = Trim(line.substr(i + 1, close - i - 1));
    std::size_t k = 0;
    while (k < inside.size() && !std::isspace(static_cast<unsigned char>(inside[k]))) ++k;
    if (k == 0) {
      *error = "empty braces at column " + std::to_string(i + 1);
      return std::nullopt;
    }
    m.Add(std::string(inside.substr(0, k)), std::string(Trim(inside.substr(k))));
    i = close + 1;
  }
  return m;
}

std::string FormatLine(const ProtocolMessage& m) {
  std::string line = m.type;
  for (const auto& [k, v] : m.fields) line += " {" + k + (v.empty() ? "" : " " + v) + "}";
  return line + "\r\n";
}

void LineReader::Append(std::string_view bytes) {
  if (start_ > 0 && start_ * 2 >= buffer_.size()) {  // most of it taken: drop that part once
    buffer_.erase(0, start_);
    start_ = 0;
  }
  buffer_.append(bytes);
}

std::optional<std::string> LineReader::Next(bool* too_long) {
  *too_long = false;
  if (partner_ && start_ < buffer_.size()) {
    if (buffer_[start_] == partner_) ++start_;
    partner_ = 0;
  }
  const std::size_t end = buffer_.find_first_of("\r\n", start_ + scanned_);
  if (end == std::string::npos) {
    scanned_ = Pending();
    if (scanned_ > max_line_) *too_long = true;
    return std::nullopt;
  }
  if (end - start_ > max_line_) {
    *too_long = true;
    return std::nullopt;
  }
  std::string line = buffer_.substr(start_, end - start_);
  std::size_t next = end + 1;
  // CR LF and LF CR count as one line end.
  if (next < buffer_.size() && (buffer_[next] == '\r' || buffer_[next] == '\n') && buffer_[next] != buffer_[end])
    ++next;
  else if (next == buffer_.size())
    partner_ = buffer_[end] == '\r' ? '\n' : '\r';
  start_ = next;
  scanned_ = 0;
  if (start_ == buffer_.size()) buffer_.clear(), start_ = 0;
  return line;
}

}  // namespace sanet::wire
