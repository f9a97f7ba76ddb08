// A map in ROS's map_server format: a YAML file (image, resolution, origin, negate,
// occupied_thresh, free_thresh, mode) naming a PGM or PNG image, read as Nav2's map server reads
// it (nav2_map_server's map_io, since Jazzy): each pixel's grey value v (a colour pixel's luma;
// any alpha below 255 makes it unknown) gives p = (255 - v) / 255, or v / 255 with `negate`;
// p >= occupied_thresh is occupied, p <= free_thresh free, anything else unknown (`trinary`) or a
// shade between (`scale`, not occupied). Row 0 of the grid is the image's bottom row: `origin`
// is the pose of the lower-left pixel. Images are read with stb_image (Debian's libstb).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "scenario/yaml_reader.h"

namespace sanet::scenario {

struct OccupancyMap {
  std::string yaml, image;         // the files, as resolved
  int width = 0, height = 0;       // cells
  double resolution = 0;           // m per cell
  std::array<double, 3> origin{};  // x, y (m) and yaw (rad) of the lower-left cell's corner
  enum Cell : std::int8_t { kUnknown = -1, kFree = 0, kOccupied = 100 };
  std::vector<std::int8_t> cells;  // row by row from the bottom: cells[row * width + column]
  std::int8_t at(int column, int row) const { return cells[static_cast<std::size_t>(row) * width + column]; }
};

// Reads the map YAML at `path` (relative paths as the caller resolved them) and its image.
// Throws ScenarioError naming the file, the line and the key, or the image and why it could not
// be read.
OccupancyMap ReadRosMap(const std::string& path);

// Writes `map` as map_server files: DIR/NAME.pgm (binary P5: 0 occupied, 254 free, 205 unknown,
// as Nav2's map saver writes them) and DIR/NAME.yaml (trinary, occupied_thresh 0.65, free_thresh
// 0.196, so that any map server reads the same cells back), each whole through a temporary file.
// Throws std::runtime_error saying what could not be written.
void WriteRosMap(const OccupancyMap& map, const std::string& dir, const std::string& name);

}  // namespace sanet::scenario
