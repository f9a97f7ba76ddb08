#include "sections/ros2_section.h"

#include <cctype>

namespace sanet::sections {

bool IsRosName(const std::string& name) {
  if (name.empty() || name.front() == '/' || name.back() == '/' || name.find("//") != std::string::npos) return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const auto c = static_cast<unsigned char>(name[i]);
    const bool starts_a_part = i == 0 || name[i - 1] == '/';
    if (!(std::isalpha(c) || c == '_' || c == '/' || (!starts_a_part && std::isdigit(c)))) return false;
  }
  return true;
}

}  // namespace sanet::sections
