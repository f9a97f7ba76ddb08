#include "core/statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sanet {

nlohmann::ordered_json Quartiles(std::vector<double> samples) {
  nlohmann::ordered_json j;
  j["count"] = samples.size();
  if (samples.empty()) return j;
  std::sort(samples.begin(), samples.end());
  const auto at = [&](double q) {
    const double pos = q * (samples.size() - 1);
    const std::size_t lo = static_cast<std::size_t>(std::floor(pos));
    const std::size_t hi = std::min(lo + 1, samples.size() - 1);
    return samples[lo] + (pos - lo) * (samples[hi] - samples[lo]);
  };
  j["min"] = samples.front();
  j["q1"] = at(0.25);
  j["median"] = at(0.5);
  j["q3"] = at(0.75);
  j["max"] = samples.back();
  j["mean"] = std::accumulate(samples.begin(), samples.end(), 0.0) / samples.size();
  return j;
}

}  // namespace sanet
