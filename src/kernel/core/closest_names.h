// For "did you mean ...?" hints: the names closest to a mistyped one.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sanet {

// Levenshtein distance, ignoring case.
std::size_t EditDistance(const std::string& a, const std::string& b);

// Up to `count` of `candidates`, closest first, that are within a few edits of `wanted`
// (at most half its length, and at least 3).
std::vector<std::string> ClosestNames(const std::string& wanted, const std::vector<std::string>& candidates,
                                      std::size_t count = 3);

// "A, B or C".
std::string OrList(const std::vector<std::string>& names);

}  // namespace sanet
