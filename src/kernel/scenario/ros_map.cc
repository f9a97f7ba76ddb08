#include "scenario/ros_map.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "core/atomic_file.h"
#include "scenario/fields.h"

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

// An image as grey values and opacity, row 0 at the top.
struct Grey {
  int width = 0, height = 0;
  std::vector<std::uint8_t> value, opaque;
};

std::string ReadBytes(const Field& f, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) f.Fail("cannot read the image " + path + ": " + std::strerror(errno));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// A binary PGM (P5) read here: its maxval (1 to 65535, two bytes big-endian above 255) scaled
// to 0..255, its size checked against its header.
Grey ReadPgm(const Field& f, const std::string& path, const std::string& bytes) {
  std::size_t at = 2;
  const auto number = [&]() -> long {
    while (at < bytes.size() && (std::isspace(static_cast<unsigned char>(bytes[at])) || bytes[at] == '#'))
      if (bytes[at] == '#')
        at = bytes.find('\n', at) == std::string::npos ? bytes.size() : bytes.find('\n', at);
      else
        ++at;
    long n = -1;
    for (; at < bytes.size() && std::isdigit(static_cast<unsigned char>(bytes[at])) && n < 1000000; ++at)
      n = (n < 0 ? 0 : n * 10) + (bytes[at] - '0');
    return n;
  };
  Grey g;
  const long width = number(), height = number(), maxval = number();
  if (width <= 0 || height <= 0 || width > 100000 || height > 100000 || maxval < 1 || maxval > 65535)
    f.Fail("the PGM " + path +
           " has no image its header can describe (width, height from 1 to 100000, maxval 1 to 65535)");
  const std::size_t depth = maxval > 255 ? 2 : 1, count = static_cast<std::size_t>(width) * height;
  ++at;  // the one white space after maxval
  if (bytes.size() < at + count * depth)
    f.Fail("the PGM " + path + " is cut short: its header says " + std::to_string(width) + " x " +
           std::to_string(height) + " pixels, the file holds " +
           std::to_string((bytes.size() - std::min(at, bytes.size())) / depth));
  g.width = static_cast<int>(width), g.height = static_cast<int>(height);
  g.value.resize(count), g.opaque.assign(count, 1);
  for (std::size_t i = 0; i < count; ++i) {
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + at + i * depth);
    const long v = depth == 2 ? p[0] * 256 + p[1] : p[0];
    g.value[i] = static_cast<std::uint8_t>(std::lround(255.0 * std::min(v, maxval) / maxval));
  }
  return g;
}

// Any other image stb_image reads (PNG above all): its luma (Rec. 601, as the map server's grey)
// and its alpha.
Grey ReadOther(const Field& f, const std::string& path, const std::string& bytes) {
  int width = 0, height = 0, channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> data(
      stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<int>(bytes.size()),
                            &width, &height, &channels, 0),
      stbi_image_free);
  if (!data)
    f.Fail("cannot read the image " + path + ": " + stbi_failure_reason() +
           " (a binary PGM, P5, or a PNG; an ASCII P2 PGM is not read: convert it, e.g. `convert in.pgm out.png`)");
  Grey g;
  g.width = width, g.height = height;
  const std::size_t count = static_cast<std::size_t>(width) * height;
  g.value.resize(count), g.opaque.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const unsigned char* p = data.get() + i * static_cast<std::size_t>(channels);
    g.value[i] =
        channels <= 2 ? p[0] : static_cast<std::uint8_t>(std::lround(0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]));
    g.opaque[i] = channels == 2 ? p[1] == 255 : channels == 4 ? p[3] == 255 : 1;
  }
  return g;
}

std::int8_t CellOf(int grey, bool opaque, const Thresholds& t) {
  if (!opaque) return OccupancyMap::kUnknown;
  const double p = t.negate ? grey / 255.0 : (255 - grey) / 255.0;
  if (p >= t.occupied) return OccupancyMap::kOccupied;
  if (p <= t.free) return OccupancyMap::kFree;
  return t.mode == Mode::kTrinary ? OccupancyMap::kUnknown : OccupancyMap::kFree;  // a shade: not a wall
}

void ReadImage(const Field& image_field, const Thresholds& t, OccupancyMap& map) {
  const std::string bytes = ReadBytes(image_field, map.image);
  const Grey g = bytes.compare(0, 2, "P5") == 0 ? ReadPgm(image_field, map.image, bytes)
                                                : ReadOther(image_field, map.image, bytes);
  map.width = g.width, map.height = g.height;
  map.cells.resize(g.value.size());
  for (int row = 0; row < g.height; ++row)  // image row 0 is the top: the grid's last
    for (int column = 0; column < g.width; ++column) {
      const std::size_t i = static_cast<std::size_t>(row) * g.width + column;
      map.cells[static_cast<std::size_t>(g.height - 1 - row) * g.width + column] = CellOf(g.value[i], g.opaque[i], t);
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
  yaml << "image: " << name << ".pgm\nmode: trinary\nresolution: " << ShortNumber(map.resolution) << "\norigin: ["
       << ShortNumber(map.origin[0]) << ", " << ShortNumber(map.origin[1]) << ", " << ShortNumber(map.origin[2])
       << "]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  WriteFileAtomically((fs::path(dir) / (name + ".pgm")).string(), pgm);
  WriteFileAtomically((fs::path(dir) / (name + ".yaml")).string(), yaml.str());
}

}  // namespace sanet::scenario
