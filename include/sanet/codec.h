// Typed messages without hand-packing: write fields in order, read them back in the same order.
// Numbers travel little-endian and doubles as IEEE 754, so the bytes are the same on every
// machine (unlike a memcpy of a struct, whose layout and padding are the compiler's).
//
//   sanet::Bytes b = sanet::Writer().U8(kHelp).Bool(ra).Bool(ma).F64(hop_time).bytes();
//   sanet::Reader r(message.payload);
//   auto kind = r.U8(); bool ra = r.Bool(); ...; if (!r.ok()) { /* malformed */ }
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <utility>

#include "sanet/message.h"

namespace sanet {

class Writer {
 public:
  Writer& U8(std::uint8_t v) { return Raw(v, 1); }
  Writer& U16(std::uint16_t v) { return Raw(v, 2); }
  Writer& U32(std::uint32_t v) { return Raw(v, 4); }
  Writer& U64(std::uint64_t v) { return Raw(v, 8); }
  Writer& I32(std::int32_t v) { return Raw(static_cast<std::uint32_t>(v), 4); }
  Writer& Bool(bool v) { return U8(v ? 1 : 0); }
  Writer& F64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    return U64(bits);
  }
  Writer& Text(const std::string& s) {
    U32(static_cast<std::uint32_t>(s.size()));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
    return *this;
  }
  const Bytes& bytes() const { return bytes_; }

 private:
  Writer& Raw(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    return *this;
  }
  Bytes bytes_;
};

// Reads fields back; reading past the end yields zeros and makes ok() false.
class Reader {
 public:
  explicit Reader(Bytes bytes) : bytes_(std::move(bytes)) {}  // its own copy: never dangles
  std::uint8_t U8() { return static_cast<std::uint8_t>(Raw(1)); }
  std::uint16_t U16() { return static_cast<std::uint16_t>(Raw(2)); }
  std::uint32_t U32() { return static_cast<std::uint32_t>(Raw(4)); }
  std::uint64_t U64() { return Raw(8); }
  std::int32_t I32() { return static_cast<std::int32_t>(U32()); }
  bool Bool() { return U8() != 0; }
  double F64() {
    const std::uint64_t bits = U64();
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
  std::string Text() {
    const std::uint32_t n = U32();
    if (!ok_ || n > bytes_.size() - pos_) {
      ok_ = false;
      return {};
    }
    std::string s(bytes_.begin() + pos_, bytes_.begin() + pos_ + n);
    pos_ += n;
    return s;
  }
  bool ok() const { return ok_; }
  // Marks what was read as malformed (a value no writer writes), as reading past the end does.
  void Fail() { ok_ = false; }
  bool at_end() const { return pos_ == bytes_.size(); }

 private:
  std::uint64_t Raw(int n) {
    if (!ok_ || bytes_.size() - pos_ < static_cast<std::size_t>(n)) {
      ok_ = false;
      return 0;
    }
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(bytes_[pos_ + i]) << (8 * i);
    pos_ += n;
    return v;
  }
  Bytes bytes_;
  std::size_t pos_ = 0;
  bool ok_ = true;
};

}  // namespace sanet
