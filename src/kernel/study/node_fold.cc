#include "study/node_fold.h"

#include <array>

#include "study/metric_expression.h"

namespace sanet::study {
namespace {

// The sections of summary.json keyed by node name.
constexpr std::array<const char*, 2> kPerNodeSections = {"metrics.", "energy.nodes."};

}  // namespace

std::string NodePattern(const std::string& name, const std::set<std::string>& nodes) {
  for (const std::string section : kPerNodeSections) {
    if (name.compare(0, section.size(), section) != 0) continue;
    std::size_t longest = 0;  // node names may hold dots: "team.a0" before "team"
    for (const std::string& node : nodes)
      if (node.size() > longest && name.compare(section.size(), node.size() + 1, node + ".") == 0)
        longest = node.size();
    if (longest > 0) return section + "*" + name.substr(section.size() + longest);
  }
  return "";
}

std::string FoldedExpression(const std::string& pattern) {
  const std::size_t dot = pattern.rfind('.');
  const std::string last = dot == std::string::npos ? pattern : pattern.substr(dot + 1);
  const char* function = last == "count" || last == "sum" ? "sum"
                         : last == "min"                  ? "min"
                         : last == "max"                  ? "max"
                                                          : "mean";
  return std::string(function) + "(" + QuotedName(pattern) + ")";
}

}  // namespace sanet::study
