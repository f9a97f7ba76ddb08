#include "core/closest_names.h"

#include <algorithm>
#include <cctype>

namespace sanet {

std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const bool same =
          std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> ClosestNames(const std::string& wanted, const std::vector<std::string>& candidates,
                                      std::size_t count) {
  std::vector<std::pair<std::size_t, std::string>> ranked;
  for (const std::string& c : candidates) ranked.emplace_back(EditDistance(wanted, c), c);
  std::sort(ranked.begin(), ranked.end());
  const std::size_t limit = std::max<std::size_t>(3, wanted.size() / 2);
  std::vector<std::string> close;
  for (const auto& [distance, name] : ranked)
    if (distance <= limit && close.size() < count && std::find(close.begin(), close.end(), name) == close.end())
      close.push_back(name);
  return close;
}

std::string OrList(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return out;
}

}  // namespace sanet
