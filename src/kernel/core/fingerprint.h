// A 64-bit FNV-1a hash over named ingredients of a run (trajectories, messages, seed ...).
// Equal fingerprints mean the runs produced the same bytes.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace sanet {

class Fingerprint {
 public:
  void Add(std::string_view bytes) {
    for (unsigned char c : bytes) {
      hash_ ^= c;
      hash_ *= 0x100000001B3ull;
    }
  }
  void Add(std::uint64_t value) { Add(std::string_view(reinterpret_cast<const char*>(&value), 8)); }
  std::uint64_t Value() const { return hash_; }
  std::string Hex() const;

 private:
  std::uint64_t hash_ = 0xCBF29CE484222325ull;
};

}  // namespace sanet
