// Five-number summaries of samples (delays, discovery times ...), as JSON for summary.json.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

namespace sanet {

// {"count", "min", "q1", "median", "q3", "max", "mean"}; only "count" for no samples.
// Quartiles by linear interpolation between order statistics.
nlohmann::ordered_json Quartiles(std::vector<double> samples);
// The q-quantile (0 <= q <= 1) by the same interpolation; 0 for no samples.
double Quantile(std::vector<double> samples, double q);

// Student's t for a two-sided 95 % interval with `dof` degrees of freedom.
double StudentT95(int dof);

// Mean and the half-width of its 95 % confidence interval (Student's t; 0 for fewer than two).
struct MeanCi {
  int count = 0;
  double mean = 0, half_width = 0;
};
MeanCi MeanWithCi(const std::vector<double>& samples);

}  // namespace sanet
