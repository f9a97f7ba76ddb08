// Random numbers addressed by what they are for rather than by when they are asked: the numbers
// for a key (say: seed, sender, receiver, instant) are always the same, however many other keys
// were drawn before and in whichever order. The radio's shadowing and fading draw this way, so
// that asking about a link (a WSS signal-strength query, the indexed channel skipping a far
// radio) never changes what another link gets. SplitMix64 (Steele, Lea and Flood, "Fast
// splittable pseudorandom number generators", OOPSLA 2014) hashes the key and then steps from it.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <limits>

namespace sanet {

// SplitMix64's output function: 64 bits mixed so that nearby inputs give unrelated outputs.
std::uint64_t SplitMix64Mix(std::uint64_t z);

class CounterRandom {
 public:
  using result_type = std::uint64_t;  // a UniformRandomBitGenerator, for <random>-style distributions

  CounterRandom(std::uint64_t seed, std::initializer_list<std::uint64_t> key);

  std::uint64_t operator()();
  double Uniform();           // [0, 1)
  double OpenUniform();       // (0, 1)
  double StandardGaussian();  // mean 0, deviation 1 (Box-Muller: one draw, no state kept)
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }

 private:
  std::uint64_t state_;
};

}  // namespace sanet
