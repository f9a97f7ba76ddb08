// A camera picture as PNG (lossless, deterministic: the same pixels, the same bytes), through
// Debian's stb_image_write: for the run's record and for agents' SEN lines. A layer that includes
// it links stb (PkgConfig::STB).
#pragma once

#include <stb/stb_image_write.h>

#include <cstdint>
#include <vector>

#include "sanet/readings.h"

namespace sanet::sensors {

inline std::vector<std::uint8_t> EncodePng(const ImageReading& picture) {
  std::vector<std::uint8_t> png;
  stbi_write_png_to_func(
      [](void* to, void* bytes, int size) {
        auto& out = *static_cast<std::vector<std::uint8_t>*>(to);
        out.insert(out.end(), static_cast<std::uint8_t*>(bytes), static_cast<std::uint8_t*>(bytes) + size);
      },
      &png, picture.width, picture.height, 3, picture.data.data(), picture.width * 3);
  return png;
}

}  // namespace sanet::sensors
