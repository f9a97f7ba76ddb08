#include "scenario/world_raster.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sanet::scenario {
namespace {

constexpr double kMargin = 1.0;       // m around what the world holds
constexpr double kMostCells = 400e6;  // 400 MB of image

struct Bounds {
  Vec2 low{HUGE_VAL, HUGE_VAL}, high{-HUGE_VAL, -HUGE_VAL};
  void Add(Vec2 p) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y)};
  }
};

// Whether the box's footprint and the square cell centred at `p` (side `side`) overlap by more
// than a hair (boxes made of cells do not spill into their neighbours): separating axes, the
// cell's two and the box's two.
bool Overlaps(const physics::StaticBox& b, Vec2 p, double side) {
  constexpr double kHair = 1e-6;
  const double c = std::cos(b.yaw), s = std::sin(b.yaw), dx = p.x - b.center.x, dy = p.y - b.center.y;
  const double hx = b.size.x / 2, hy = b.size.y / 2, h = side / 2;
  // The box's half extent along the world's x and y, and the cell's along the box's axes.
  const bool apart_x = std::fabs(dx) >= hx * std::fabs(c) + hy * std::fabs(s) + h - kHair * side;
  const bool apart_y = std::fabs(dy) >= hx * std::fabs(s) + hy * std::fabs(c) + h - kHair * side;
  const double cell_extent = h * (std::fabs(c) + std::fabs(s));
  const bool apart_u = std::fabs(c * dx + s * dy) >= hx + cell_extent - kHair * side;
  const bool apart_v = std::fabs(-s * dx + c * dy) >= hy + cell_extent - kHair * side;
  return !(apart_x || apart_y || apart_u || apart_v);
}

Bounds WorldBounds(const sim::RunSpec& spec) {
  Bounds b;
  for (const sim::Obstacle& o : spec.obstacles)
    for (const Vec2 corner : physics::FootprintCorners(o.box)) b.Add(corner);
  for (const sim::NodeSpec& n : spec.nodes) b.Add({n.pose.x, n.pose.y});
  if (b.low.x > b.high.x) b.Add({0, 0});
  b.low = b.low - Vec2{kMargin, kMargin}, b.high = b.high + Vec2{kMargin, kMargin};
  return b;
}

// Where the grid's lines fall: on the world map's when it has one of this resolution and no turn.
Vec2 Anchor(const sim::RunSpec& spec, double resolution) {
  if (spec.map && std::fabs(spec.map->resolution - resolution) <= 1e-6 * resolution && spec.map->origin[2] == 0)
    return {spec.map->origin[0], spec.map->origin[1]};
  return {0, 0};
}

}  // namespace

OccupancyMap RasterizeWorld(const sim::RunSpec& spec, double resolution) {
  const Bounds b = WorldBounds(spec);
  const Vec2 anchor = Anchor(spec, resolution);
  OccupancyMap map;
  map.resolution = resolution;
  // (1e-6 of a cell: a bound on a grid line stays on it whatever the rounding)
  const double x0 = anchor.x + std::floor((b.low.x - anchor.x) / resolution + 1e-6) * resolution;
  const double y0 = anchor.y + std::floor((b.low.y - anchor.y) / resolution + 1e-6) * resolution;
  map.origin = {x0, y0, 0};
  const double columns = std::ceil((b.high.x - x0) / resolution - 1e-6);
  const double rows = std::ceil((b.high.y - y0) / resolution - 1e-6);
  if (columns * rows > kMostCells)
    throw std::invalid_argument("the world is " + std::to_string(static_cast<long long>(columns)) + " x " +
                                std::to_string(static_cast<long long>(rows)) +
                                " cells of that size: take a coarser one");
  map.width = static_cast<int>(columns), map.height = static_cast<int>(rows);
  map.cells.assign(static_cast<std::size_t>(map.width) * map.height, OccupancyMap::kFree);
  for (const sim::Obstacle& o : spec.obstacles) {
    Bounds box;
    for (const Vec2 corner : physics::FootprintCorners(o.box)) box.Add(corner);
    const int c0 = std::max(0, static_cast<int>(std::floor((box.low.x - x0) / resolution)));
    const int c1 = std::min(map.width - 1, static_cast<int>(std::floor((box.high.x - x0) / resolution)));
    const int r0 = std::max(0, static_cast<int>(std::floor((box.low.y - y0) / resolution)));
    const int r1 = std::min(map.height - 1, static_cast<int>(std::floor((box.high.y - y0) / resolution)));
    for (int row = r0; row <= r1; ++row)
      for (int column = c0; column <= c1; ++column)
        if (Overlaps(o.box, {x0 + (column + 0.5) * resolution, y0 + (row + 0.5) * resolution}, resolution))
          map.cells[static_cast<std::size_t>(row) * map.width + column] = OccupancyMap::kOccupied;
  }
  return map;
}

}  // namespace sanet::scenario
