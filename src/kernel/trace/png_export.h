// PNG copies of the SVG figures, drawn by librsvg's rsvg-convert (Debian's librsvg2-bin), the
// renderer the figures are tested with.
#pragma once

#include <string>

namespace sanet::trace {

// Whether rsvg-convert can be run here.
bool PngExportAvailable();
// Renders `svg` (a file) to `png` at `scale` times its size; false if rsvg-convert failed.
bool SvgToPng(const std::string& svg, const std::string& png, double scale = 2);

}  // namespace sanet::trace
