#include "core/counter_random.h"

#include <cmath>

namespace sanet {
namespace {

constexpr std::uint64_t kGolden = 0x9E3779B97F4A7C15ull;

}  // namespace

std::uint64_t SplitMix64Mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Each part of the key is mixed in after a step of its own, so (1, 2) and (2, 1) differ.
CounterRandom::CounterRandom(std::uint64_t seed, std::initializer_list<std::uint64_t> key)
    : state_(SplitMix64Mix(seed + kGolden)) {
  for (std::uint64_t part : key) state_ = SplitMix64Mix(state_ + kGolden + SplitMix64Mix(part + kGolden));
}

std::uint64_t CounterRandom::operator()() { return SplitMix64Mix(state_ += kGolden); }

double CounterRandom::Uniform() { return static_cast<double>((*this)() >> 11) * 0x1.0p-53; }

double CounterRandom::OpenUniform() { return (static_cast<double>((*this)() >> 11) + 0.5) * 0x1.0p-53; }

double CounterRandom::StandardGaussian() {
  const double radius = std::sqrt(-2 * std::log(OpenUniform()));
  return radius * std::cos(2 * M_PI * Uniform());
}

}  // namespace sanet
