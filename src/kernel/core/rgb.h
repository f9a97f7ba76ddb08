// A colour as scenarios write it, "#rrggbb": 8 bits a channel, for what cameras see.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace sanet {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

// "#rrggbb" (either case); nothing for any other text.
std::optional<Rgb> ParseRgb(const std::string& text);
std::string RgbText(Rgb c);  // "#rrggbb", lower case

}  // namespace sanet
