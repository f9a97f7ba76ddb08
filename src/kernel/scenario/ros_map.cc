#include "scenario/ros_map.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "core/atomic_file.h"

namespace sanet::scenario {
namespace {

namespace fs = std::filesystem;

enum class Mode { kTrinary, kScale };

struct Thresholds {
  double occupied = 0.65, free = 0.196;
  bool negate = false;
  Mode mode = Mode::kTrinary;
};

// `negate: 0` or `negate: false`, as map servers take either.
bool ReadNegate(const Field& f) {
  if (f.IsScalar() && (f.node().Scalar() == "0" || f.node().Scalar() == "1")) return f.node().Scalar() == "1";
  return f.Bool();
}

Mode ReadMode(const std::optional<Field>& f) {
  if (!f) return Mode::kTrinary;
  std::string mode = f->Text();
  std::transform(mode.begin(), mode.end(), mode.begin(), [](unsigned char c) { return std::tolower(c); });
  if (mode == "trinary") return Mode::kTrinary;
  if (mode == "scale") return Mode::kScale;
  if (mode == "raw") f->Fail("`raw` maps hold occupancy values, not an image of the building: give trinary or scale");
  f->Fail("unknown mode '" + f->Text() + "' (expected trinary or scale)");
}

// The grey value and whether the pixel is opaque, of pixel `i` of an image of `channels`.
std::pair<int, bool> Pixel(const unsigned char* data, std::size_t i, int channels) {
  const unsigned char* p = data + i * static_cast<std::size_t>(channels);
  if (channels <= 2) return {p[0], channels == 1 || p[1] == 255};
  const int luma = (77 * p[0] + 150 * p[1] + 29 * p[2]) >> 8;  // Rec. 601, as the map server's grey
  return {luma, channels == 3 || p[3] == 255};
}

std::int8_t CellOf(int grey, bool opaque, const Thresholds& t) {
  if (!opaque) return OccupancyMap::kUnknown;
  const double p = t.negate ? grey / 255.0 : (255 - grey) / 255.0;
  if (p >= t.occupied) return OccupancyMap::kOccupied;
  if (p <= t.free) return OccupancyMap::kFree;
  return t.mode == Mode::kTrinary ? OccupancyMap::kUnknown : OccupancyMap::kFree;  // a shade: not a wall
}

void ReadImage(const Field& image_field, const Thresholds& t, OccupancyMap& map) {
  int width = 0, height = 0, channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> data(stbi_load(map.image.c_str(), &width, &height, &channels, 0),
                                                       stbi_image_free);
  if (!data)
    image_field.Fail("cannot read the image " + map.image + ": " + stbi_failure_reason() +
                     " (PGM P5 or PNG, 8-bit; an ASCII P2 PGM is not read: convert it, e.g. `convert in.pgm out.png`)");
  map.width = width, map.height = height;
  map.cells.resize(static_cast<std::size_t>(width) * height);
  for (int row = 0; row < height; ++row)  // image row 0 is the top: the grid's last
    for (int column = 0; column < width; ++column) {
      const auto [grey, opaque] = Pixel(data.get(), static_cast<std::size_t>(row) * width + column, channels);
      map.cells[static_cast<std::size_t>(height - 1 - row) * width + column] = CellOf(grey, opaque, t);
    }
}

std::string Resolve(const std::string& yaml, const std::string& image) {
  const fs::path path(image);
  return (path.is_relative() ? fs::path(yaml).parent_path() / path : path).lexically_normal().string();
}

}  // namespace

OccupancyMap ReadRosMap(const std::string& path) {
  const Field root = ParseYamlFile(path, "a ROS map's YAML");
  OccupancyMap map;
  map.yaml = path;
  const Field image = root.Require("image");
  if (image.Text().empty()) image.Fail("names no image");
  map.image = Resolve(path, image.Text());
  map.resolution = root.Require("resolution").NumberAbove(0, 1e3);
  const std::vector<double> origin = root.Require("origin").Numbers(3);
  map.origin = {origin[0], origin[1], origin[2]};
  Thresholds t;
  t.negate = ReadNegate(root.Require("negate"));
  t.occupied = root.Require("occupied_thresh").Number(0, 1);
  t.free = root.Require("free_thresh").Number(0, 1);
  if (t.free >= t.occupied) root.Require("free_thresh").Fail("must be below occupied_thresh");
  t.mode = ReadMode(root.Get("mode"));
  ReadImage(image, t, map);
  return map;
}

void WriteRosMap(const OccupancyMap& map, const std::string& dir, const std::string& name) {
  std::error_code ignored;
  fs::create_directories(dir, ignored);
  std::string pgm =
      "P5\n# CREATOR: sanet map\n" + std::to_string(map.width) + " " + std::to_string(map.height) + "\n255\n";
  const std::size_t header = pgm.size();
  pgm.resize(header + map.cells.size());
  for (int row = 0; row < map.height; ++row)
    for (int column = 0; column < map.width; ++column) {
      const std::int8_t cell = map.at(column, map.height - 1 - row);
      pgm[header + static_cast<std::size_t>(row) * map.width + column] =
          static_cast<char>(cell == OccupancyMap::kOccupied ? 0
                            : cell == OccupancyMap::kFree   ? 254
                                                            : 205);
    }
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "image: " << name << ".pgm\nmode: trinary\nresolution: " << map.resolution << "\norigin: [" << map.origin[0]
       << ", " << map.origin[1] << ", " << map.origin[2] << "]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  WriteFileAtomically((fs::path(dir) / (name + ".pgm")).string(), pgm);
  WriteFileAtomically((fs::path(dir) / (name + ".yaml")).string(), yaml.str());
}

}  // namespace sanet::scenario
