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

double StudentT95(int dof) {
  static const double table[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                 2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                 2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof < 1) return 0;
  if (dof <= 30) return table[dof - 1];
  const double z = 1.959964;  // beyond the table, the first Cornish-Fisher term (within 0.001 at 31)
  return z + (z * z * z + z) / (4.0 * dof);
}

MeanCi MeanWithCi(const std::vector<double>& samples) {
  MeanCi m;
  m.count = static_cast<int>(samples.size());
  if (samples.empty()) return m;
  double sum = 0;
  for (double v : samples) sum += v;
  m.mean = sum / m.count;
  if (m.count < 2) return m;
  double squares = 0;
  for (double v : samples) squares += (v - m.mean) * (v - m.mean);
  const double sd = std::sqrt(squares / (m.count - 1));
  m.half_width = StudentT95(m.count - 1) * sd / std::sqrt(static_cast<double>(m.count));
  return m;
}

}  // namespace sanet
