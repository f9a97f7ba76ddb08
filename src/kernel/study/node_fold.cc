#include "study/node_fold.h"

namespace sanet::study {

std::string NodePattern(const std::string& name, const std::set<std::string>& nodes) {
  const std::size_t first = name.find('.');
  if (first == std::string::npos) return "";
  for (std::size_t start = first + 1; start < name.size();) {
    std::size_t end = name.find('.', start);
    if (end == std::string::npos) end = name.size();
    if (nodes.count(name.substr(start, end - start))) return name.substr(0, start) + "*" + name.substr(end);
    start = end + 1;
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
  return std::string(function) + "(" + pattern + ")";
}

}  // namespace sanet::study
