#include "core/random_stream.h"

#include <cmath>

#include "core/counter_random.h"
#include "core/fingerprint.h"

namespace sanet {
namespace {

std::uint64_t SplitMix64(std::uint64_t& x) { return SplitMix64Mix(x += 0x9E3779B97F4A7C15ull); }

std::uint64_t Rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

}  // namespace

RandomStream::RandomStream(std::uint64_t seed, const std::string& stream) {
  Fingerprint name;
  name.Add(stream);
  std::uint64_t x = seed ^ name.Value();
  for (auto& s : s_) s = SplitMix64(x);
}

std::uint64_t RandomStream::NextU64() {
  const std::uint64_t result = Rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = Rotl(s_[3], 45);
  return result;
}

double RandomStream::Uniform() { return static_cast<double>(NextU64() >> 11) * 0x1.0p-53; }

double RandomStream::Gaussian(double mean, double stddev) {
  if (has_spare_) {
    has_spare_ = false;
    return mean + stddev * spare_;
  }
  // Marsaglia's polar method: exact, and needs only sqrt and log.
  double u, v, s;
  do {
    u = 2 * Uniform() - 1;
    v = 2 * Uniform() - 1;
    s = u * u + v * v;
  } while (s >= 1 || s == 0);
  const double k = std::sqrt(-2 * std::log(s) / s);
  spare_ = v * k;
  has_spare_ = true;
  return mean + stddev * u * k;
}

}  // namespace sanet
