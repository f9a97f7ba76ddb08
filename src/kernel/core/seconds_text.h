// A time for people to read in a sentence: "12.5 s".
#pragma once

#include <cstdio>
#include <string>

namespace sanet {

inline std::string SecondsText(double seconds, int decimals = 1) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f s", decimals, seconds);
  return text;
}

}  // namespace sanet
