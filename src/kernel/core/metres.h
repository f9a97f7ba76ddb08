// A length for a sentence meant for people: two decimals, never "-0.00".
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace sanet {

inline std::string Metres(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", std::fabs(v) < 0.005 ? 0.0 : v);
  return text;
}

}  // namespace sanet
