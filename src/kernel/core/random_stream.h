// Seeded random numbers, one independent stream per consumer. The generator (SplitMix64 seeding
// a xoshiro256**) and the Gaussian transform are written here rather than taken from <random>,
// whose distributions differ between standard libraries: the same (seed, stream) must give the
// same numbers everywhere.
#pragma once

#include <cstdint>
#include <string>

namespace sanet {

class RandomStream {
 public:
  // `stream` names the consumer, e.g. "node/3/ir"; different names give independent streams.
  RandomStream(std::uint64_t seed, const std::string& stream);

  std::uint64_t NextU64();
  double Uniform();  // [0, 1)
  double Gaussian(double mean, double stddev);

 private:
  std::uint64_t s_[4];
  bool has_spare_ = false;
  double spare_ = 0;
};

}  // namespace sanet
