// Per-node metrics folded by name, so that a study of 30 motes lists `metrics.*.created.count`
// once instead of 30 times: in summary.json's sections keyed by node (`metrics.<node>...` and
// `energy.nodes.<node>...`), the node's name becomes `*`.
#pragma once

#include <set>
#include <string>

namespace sanet::study {

// The folded pattern of `name`, or "" when it is not a metric of one of `nodes`.
std::string NodePattern(const std::string& name, const std::set<std::string>& nodes);
// What a folded metric is by default, as an expression: counts and sums add up over the nodes,
// minima and maxima stay minima and maxima, every other statistic is averaged:
// `sum(metrics.*.created.count)`, `mean(energy.nodes.*.remaining_j)`.
std::string FoldedExpression(const std::string& pattern);

}  // namespace sanet::study
