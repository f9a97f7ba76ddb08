#include "ros2msg/cdr.h"

namespace sanet::ros2msg {

void CdrWriter::PutString(const std::string& s) {
  PutCount(s.size() + 1);
  out_.insert(out_.end(), s.begin(), s.end());
  out_.push_back(0);
}

Bytes CdrWriter::Take() {
  const std::size_t padding = (4 - out_.size() % 4) % 4;
  out_.resize(out_.size() + padding, 0);
  out_[3] = static_cast<std::uint8_t>(padding);
  return std::move(out_);
}

CdrReader::CdrReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {
  if (size < 4) {
    Fail("encapsulation", "fewer than the 4 bytes of the encapsulation header");
  } else if (data[0] != 0 || data[1] > 1) {
    Fail("encapsulation", "not plain CDR (header " + std::to_string(data[0]) + " " + std::to_string(data[1]) +
                              "; ROS 2 sends 0 1, little endian, or 0 0, big endian)");
  } else {
    swap_ = data[1] == 0;  // big endian on the wire
  }
}

bool CdrReader::Fail(const char* field, const std::string& why) {
  if (error_.empty()) error_ = std::string(field) + ": " + why;
  at_ = size_;
  return false;
}

bool CdrReader::Need(std::size_t n, const char* field) {
  if (!ok()) return false;
  if (n > size_ - at_)
    return Fail(field, "needs " + std::to_string(n) + " bytes, " + std::to_string(size_ - at_) + " left");
  return true;
}

bool CdrReader::Align(std::size_t n, const char* field) {
  if (!ok()) return false;
  const std::size_t pad = (n - (at_ - 4) % n) % n;
  if (!Need(pad, field)) return false;
  at_ += pad;
  return true;
}

bool CdrReader::Get(bool& value, const char* field) {
  std::uint8_t raw = 0;
  if (!Get(raw, field)) return false;
  if (raw > 1) return Fail(field, "a boolean of " + std::to_string(raw));
  value = raw == 1;
  return true;
}

bool CdrReader::GetString(std::string& s, std::size_t bound, const char* field) {
  std::uint32_t n = 0;
  if (!Get(n, field)) return false;
  if (n == 0) return Fail(field, "a string of length 0 (CDR counts the closing NUL)");
  if (!Need(n, field)) return false;
  if (data_[at_ + n - 1] != 0) return Fail(field, "a string without its closing NUL");
  if (bound && n - 1 > bound)
    return Fail(field, "a string of " + std::to_string(n - 1) + " bytes, over its bound of " + std::to_string(bound));
  s.assign(reinterpret_cast<const char*>(data_ + at_), n - 1);
  at_ += n;
  return true;
}

bool CdrReader::GetCount(std::uint32_t& n, std::size_t bound, std::size_t least, const char* field) {
  if (!Get(n, field)) return false;
  if (bound && n > bound)
    return Fail(field, "a sequence of " + std::to_string(n) + ", over its bound of " + std::to_string(bound));
  if (least && n > left() / least)
    return Fail(field, "a sequence of " + std::to_string(n) + " elements, in " + std::to_string(left()) + " bytes");
  return true;
}

}  // namespace sanet::ros2msg
