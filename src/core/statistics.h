// Five-number summaries of samples (delays, discovery times ...), as JSON for summary.json.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

namespace sanet {

// {"count", "min", "q1", "median", "q3", "max", "mean"}; only "count" for no samples.
// Quartiles by linear interpolation between order statistics.
nlohmann::ordered_json Quartiles(std::vector<double> samples);

}  // namespace sanet
