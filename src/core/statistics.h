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

}  // namespace sanet
