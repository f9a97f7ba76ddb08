// A camera picture as PNG (lossless, deterministic: the same pixels, the same bytes), for the
// run's record and for agents' SEN lines (sensors/camera/png.cc).
#pragma once

#include <cstdint>
#include <vector>

#include "sanet/readings.h"

namespace sanet::sensors {

std::vector<std::uint8_t> EncodePng(const ImageReading& picture);

}  // namespace sanet::sensors
