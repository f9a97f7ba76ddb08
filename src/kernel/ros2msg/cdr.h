// CDR as ROS 2 puts it on DDS (XCDR1, "plain CDR"; rmw_cyclonedds): a 4-byte encapsulation
// header (00 01 for little endian, then two bytes of options), then the fields in order, each
// primitive aligned to its size (at most 8) counted from the end of the header; strings as a
// uint32 length that counts a closing NUL, the bytes and the NUL; sequences as a uint32 count
// and the elements; fixed arrays as their elements. The payload is padded to a multiple of 4,
// the options' last two bits saying by how many bytes (DDS-XTypes 7.6.3.1.2), as Cyclone DDS
// writes it. The writer writes little endian; the reader takes either byte order and
// says which field failed and why (a count larger than the bytes left, a string without its NUL,
// a bound exceeded), never reading past the end.
#pragma once

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace sanet::ros2msg {

using Bytes = std::vector<std::uint8_t>;

class CdrWriter {
 public:
  CdrWriter() : out_{0x00, 0x01, 0x00, 0x00} {}
  template <typename T>
  void Put(T value) {
    static_assert(std::is_arithmetic_v<T>);
    Align(sizeof(T));
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);  // this machine is little endian
    out_.insert(out_.end(), p, p + sizeof(T));
  }
  void Put(bool value) { out_.push_back(value ? 1 : 0); }
  void PutString(const std::string& s);
  void PutCount(std::size_t n) { Put(static_cast<std::uint32_t>(n)); }
  Bytes Take();

 private:
  void Align(std::size_t n) {
    while ((out_.size() - kHeader) % n) out_.push_back(0);
  }
  static constexpr std::size_t kHeader = 4;
  Bytes out_;
};

class CdrReader {
 public:
  // Checks the encapsulation header; a bad one is the reader's first error.
  CdrReader(const std::uint8_t* data, std::size_t size);
  template <typename T>
  bool Get(T& value, const char* field) {
    static_assert(std::is_arithmetic_v<T>);
    if (!Align(sizeof(T), field) || !Need(sizeof(T), field)) return false;
    std::uint8_t raw[sizeof(T)];
    std::memcpy(raw, data_ + at_, sizeof(T));
    if (swap_)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    std::memcpy(&value, raw, sizeof(T));
    at_ += sizeof(T);
    return true;
  }
  bool Get(bool& value, const char* field);
  // `bound`: the definition's string<=N (0: none).
  bool GetString(std::string& s, std::size_t bound, const char* field);
  // A sequence's count: within its bound (0: none) and within what `least` bytes per element
  // leave room for, so that a forged count cannot make the decoder allocate without end.
  bool GetCount(std::uint32_t& n, std::size_t bound, std::size_t least, const char* field);

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  std::size_t left() const { return size_ - at_; }

 private:
  bool Align(std::size_t n, const char* field);
  bool Need(std::size_t n, const char* field);
  bool Fail(const char* field, const std::string& why);
  const std::uint8_t* data_;
  std::size_t size_, at_ = 4;
  bool swap_ = false;
  std::string error_;
};

// What a generated message type is: its ROS 2 name (pkg/msg/Name), its DDS type name, and its
// definition with those of the types it uses (the schema ROS 2 tools expect).
template <typename Message>
struct TypeOf;

}  // namespace sanet::ros2msg
