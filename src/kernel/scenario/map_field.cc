#include "scenario/map_field.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "scenario/declarations.h"
#include "scenario/map_boxes.h"
#include "scenario/ros_map.h"

namespace sanet::scenario {
namespace {

constexpr std::size_t kMostBoxes = 200000;  // past it a map is noise: the physics and radio would crawl
constexpr double kWidest = 1e5;             // m, a map's side at most

constexpr const char* kKeys[] = {"file",  "height",     "thickness", "material", "unknown", "indoor",
                                 "color", "resolution", "origin",    "cells",    "boxes"};

// The map's files, read now: the scenario's own map.
void FromFile(const Field& v, sim::WorldMap& m) {
  std::filesystem::path path(m.file);
  if (path.is_relative()) path = std::filesystem::path(v.file()).parent_path() / path;
  if (!std::filesystem::exists(path)) v.Require("file").Fail("no map file " + path.lexically_normal().string());
  const OccupancyMap map = ReadRosMap(path.lexically_normal().string());
  m.resolution = map.resolution, m.origin = map.origin, m.columns = map.width, m.rows = map.height;
  if (std::max(map.width, map.height) * map.resolution > kWidest)
    v.Require("file").Fail("the map is " + std::to_string(map.width) + " x " + std::to_string(map.height) +
                           " cells of " + ShortNumber(map.resolution) + " m: more than 100 km across");
  const bool unknown_blocked = m.unknown_blocked;
  for (const CellRect& r : MergeCells(map.width, map.height, [&](int column, int row) {
         const std::int8_t cell = map.at(column, row);
         return cell == OccupancyMap::kOccupied || (unknown_blocked && cell == OccupancyMap::kUnknown);
       }))
    m.boxes.push_back({r.column, r.row, r.columns, r.rows});
  if (m.boxes.size() > kMostBoxes)
    v.Require("file").Fail("the map's blocked cells make " + std::to_string(m.boxes.size()) +
                           " boxes (more than 200,000): a map this scattered is noise, not walls; clean it (or with "
                           "`unknown: blocked`, try `free`)");
}

// The boxes as the effective scenario printed them.
void FromBoxes(const Field& v, sim::WorldMap& m) {
  m.resolution = v.Require("resolution").NumberAbove(0, 1e3);
  const std::vector<double> origin = v.Require("origin").Numbers(3);
  m.origin = {origin[0], origin[1], origin[2]};
  const std::vector<Field> cells = v.Require("cells").Items();
  if (cells.size() != 2) v.Require("cells").Fail("must be [columns, rows]");
  m.columns = cells[0].Integer(1, 100000), m.rows = cells[1].Integer(1, 100000);
  if (std::max(m.columns, m.rows) * m.resolution > kWidest) v.Require("cells").Fail("more than 100 km across");
  const std::vector<Field> boxes = v.Require("boxes").Items();
  if (boxes.size() > kMostBoxes) v.Require("boxes").Fail("more than 200,000 boxes");
  for (const Field& box : boxes) {
    const std::vector<Field> b = box.Items();
    if (b.size() != 4) box.Fail("a box is [column, row, columns, rows]");
    const int column = b[0].Integer(0, m.columns - 1), row = b[1].Integer(0, m.rows - 1);
    m.boxes.push_back({column, row, b[2].Integer(1, m.columns - column), b[3].Integer(1, m.rows - row)});
  }
}

void ReadWorldMap(const Field& v, sim::RunSpec& s) {
  v.ExpectKeys(std::vector<std::string>(std::begin(kKeys), std::end(kKeys)));
  sim::WorldMap m;
  m.file = v.Require("file").Text();
  if (auto height = v.Get("height")) m.wall_height = height->NumberAbove(0, 1000);
  if (auto thickness = v.Get("thickness")) m.wall_thickness = thickness->NumberAbove(0, 100);
  if (auto material = v.Get("material")) m.material = ReadMaterial(*material);
  if (auto unknown = v.Get("unknown")) {
    const std::string text = unknown->Text();
    if (text != "free" && text != "blocked") unknown->Fail("unknown value '" + text + "' (expected free or blocked)");
    m.unknown_blocked = text == "blocked";
  }
  if (auto indoor = v.Get("indoor")) m.indoor = indoor->Bool();
  if (auto color = v.Get("color")) m.color = ReadColor(*color);
  if (v.Get("boxes")) {
    FromBoxes(v, m);
  } else {
    for (const char* key : {"resolution", "origin", "cells"})  // they describe the boxes
      if (auto given = v.Get(key)) given->Fail("goes with `boxes` (the effective scenario's); the map file gives it");
    FromFile(v, m);
  }
  AppendMapObstacles(m, s.obstacles);
  s.map = std::move(m);
}

YAML::Node PrintWorldMap(const sim::RunSpec& s) {
  if (!s.map) return YAML::Node();
  const sim::WorldMap& m = *s.map;
  YAML::Node out;
  out["file"] = m.file;
  out["height"] = NumberNode(m.wall_height);
  out["thickness"] = NumberNode(m.wall_thickness);
  if (m.material) out["material"] = net::MaterialName(*m.material);
  out["unknown"] = m.unknown_blocked ? "blocked" : "free";
  if (m.indoor) out["indoor"] = true;
  if (m.color) out["color"] = RgbText(*m.color);
  out["resolution"] = NumberNode(m.resolution);
  YAML::Node origin(YAML::NodeType::Sequence), cells(YAML::NodeType::Sequence), boxes(YAML::NodeType::Sequence);
  for (double o : m.origin) origin.push_back(NumberNode(o));
  cells.push_back(m.columns), cells.push_back(m.rows);
  origin.SetStyle(YAML::EmitterStyle::Flow), cells.SetStyle(YAML::EmitterStyle::Flow);
  for (const auto& b : m.boxes) {
    YAML::Node box(YAML::NodeType::Sequence);
    for (int n : b) box.push_back(n);
    box.SetStyle(YAML::EmitterStyle::Flow);
    boxes.push_back(box);
  }
  out["origin"] = origin, out["cells"] = cells, out["boxes"] = boxes;
  return out;
}

}  // namespace

void AppendMapObstacles(const sim::WorldMap& m, std::vector<sim::Obstacle>& obstacles) {
  const double c = std::cos(m.origin[2]), s = std::sin(m.origin[2]), r = m.resolution;
  for (const auto& [column, row, columns, rows] : m.boxes) {
    // The box's centre in the map's frame, turned by the origin's yaw about its corner.
    const double x = (column + columns / 2.0) * r, y = (row + rows / 2.0) * r;
    sim::Obstacle o{"map",
                    {{m.origin[0] + c * x - s * y, m.origin[1] + s * x + c * y, m.wall_height / 2},
                     {columns * r, rows * r, m.wall_height},
                     m.origin[2]},
                    m.material,
                    {}};
    o.from_map = true;
    obstacles.push_back(o);
  }
}

void AddWorldMap(Fields<sim::RunSpec>& f) {
  f.Custom({"map", "mapping `{file, height, thickness, material, unknown, indoor, color}`", "", "none", "",
            "a building from a ROS map (map_server's YAML and image): see [world.map](#worldmap)"},
           ReadWorldMap, PrintWorldMap);
}

}  // namespace sanet::scenario
