#include "core/statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sanet {

namespace {

double SortedQuantile(const std::vector<double>& sorted, double q) {
  const double pos = q * (sorted.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (pos - lo) * (sorted[hi] - sorted[lo]);
}

}  // namespace

double Quantile(std::vector<double> samples, double q) {
  if (samples.empty()) return 0;
  std::sort(samples.begin(), samples.end());
  return SortedQuantile(samples, q);
}

nlohmann::ordered_json Quartiles(std::vector<double> samples) {
  nlohmann::ordered_json j;
  j["count"] = samples.size();
  if (samples.empty()) return j;
  std::sort(samples.begin(), samples.end());
  const auto at = [&](double q) { return SortedQuantile(samples, q); };
  j["min"] = samples.front();
  j["q1"] = at(0.25);
  j["median"] = at(0.5);
  j["q3"] = at(0.75);
  j["max"] = samples.back();
  j["mean"] = std::accumulate(samples.begin(), samples.end(), 0.0) / samples.size();
  return j;
}

}  // namespace sanet
