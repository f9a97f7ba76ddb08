#include "sim/surroundings_of.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace sanet::sim {
namespace {

using sensors::Region;

Region Footprint(const physics::StaticBox& box) {
  const auto corners = physics::FootprintCorners(box);
  return Region(corners.begin(), corners.end());
}

double Cross(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

double PointToSegment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double length2 = Dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(Dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return Norm(p - (a + ab * t));
}

bool SegmentsCross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return Cross(a, b, c) * Cross(a, b, d) <= 0 && Cross(c, d, a) * Cross(c, d, b) <= 0;
}

// The gap between two convex footprints: 0 where they touch or overlap.
double Gap(const Region& p, const Region& q) {
  if (sensors::Inside(p, q[0]) || sensors::Inside(q, p[0])) return 0;
  double gap = HUGE_VAL;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < q.size(); ++j) {
      const Vec2 a = p[i], b = p[(i + 1) % p.size()], c = q[j], d = q[(j + 1) % q.size()];
      if (SegmentsCross(a, b, c, d)) return 0;
      gap = std::min({gap, PointToSegment(a, c, d), PointToSegment(c, a, b)});
    }
  return gap;
}

// Andrew's monotone chain, counter-clockwise.
Region ConvexHull(Region points) {
  std::sort(points.begin(), points.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  Region hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {  // lower
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper
    while (k >= lower && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

std::size_t Root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// world.map's extent: its cells' rectangle, turned by its origin's yaw about the origin.
Region MapExtent(const WorldMap& map) {
  const double c = std::cos(map.origin[2]), s = std::sin(map.origin[2]);
  const double w = map.columns * map.resolution, h = map.rows * map.resolution;
  Region corners;
  for (const auto& [u, v] : {std::pair{0.0, 0.0}, {w, 0.0}, {w, h}, {0.0, h}})
    corners.push_back({map.origin[0] + c * u - s * v, map.origin[1] + s * u + c * v});
  return corners;
}

}  // namespace

std::vector<Region> Buildings(const std::vector<Obstacle>& obstacles) {
  std::vector<Region> footprints;
  for (const Obstacle& o : obstacles)
    if (o.indoor) footprints.push_back(Footprint(o.box));
  std::vector<std::size_t> parent(footprints.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < footprints.size(); ++i)
    for (std::size_t j = i + 1; j < footprints.size(); ++j)
      if (Gap(footprints[i], footprints[j]) < kDoorway) parent[Root(parent, i)] = Root(parent, j);
  std::vector<Region> corners(footprints.size());
  for (std::size_t i = 0; i < footprints.size(); ++i) {
    Region& group = corners[Root(parent, i)];
    group.insert(group.end(), footprints[i].begin(), footprints[i].end());
  }
  std::vector<Region> buildings;
  for (const Region& group : corners)
    if (!group.empty()) buildings.push_back(ConvexHull(group));
  return buildings;
}

Rgb DefaultBodyColor(robots::ModelKind kind) {
  switch (kind) {
    case robots::ModelKind::kDiffDrive:
      return {200, 70, 50};
    case robots::ModelKind::kOmni3:
      return {50, 100, 200};
    default:
      return {230, 190, 40};
  }
}

sensors::SceneBody SceneBodyOf(NodeId node, const robots::ModelSpec& model, const Pose2D& pose) {
  const robots::BodyShape shape = model.model().Shape(model);
  sensors::SceneBody b;
  b.node = node, b.box = shape.box, b.length = shape.length, b.width = shape.width, b.radius = shape.radius;
  b.height = shape.height, b.base = shape.base, b.pose = pose;
  b.color = model.color.value_or(DefaultBodyColor(model.kind));
  return b;
}

sensors::Surroundings SurroundingsOf(const RunSpec& spec) {
  sensors::Surroundings s;
  s.scenery.ground = spec.ground_color, s.scenery.sky = spec.sky_color;
  for (const Obstacle& o : spec.obstacles)
    s.scenery.boxes.push_back({o.box.center, o.box.size, o.box.yaw,
                               o.color.value_or(o.from_map ? spec.map->color.value_or(kMapColor) : kObstacleColor)});
  s.datum = spec.datum;
  s.gnss_denied = spec.gnss_denied;
  for (Region& building : Buildings(spec.obstacles)) s.gnss_denied.push_back(std::move(building));
  if (spec.map && spec.map->indoor) s.gnss_denied.push_back(MapExtent(*spec.map));
  return s;
}

namespace {

std::string Corners(const Region& region) {
  std::string text;
  char point[64];
  for (Vec2 p : region) {
    std::snprintf(point, sizeof point, "%s(%.2f, %.2f)", text.empty() ? "" : ", ", p.x, p.y);
    text += point;
  }
  return text;
}

}  // namespace

std::string DescribeSurroundings(const RunSpec& spec) {
  const std::vector<Region> buildings = Buildings(spec.obstacles);
  if (!spec.datum && spec.gnss_denied.empty() && buildings.empty() && !(spec.map && spec.map->indoor)) return "";
  char datum[128] = "no world.datum (a gnss sensor needs one)";
  if (spec.datum)
    std::snprintf(datum, sizeof datum, "the datum %.7f, %.7f, %.2f m", spec.datum->latitude, spec.datum->longitude,
                  spec.datum->altitude);
  std::string text = std::string("satellite fixes: ") + datum + "; none in " + std::to_string(spec.gnss_denied.size()) +
                     " region(s) of world.gnss_denied";
  if (spec.map && spec.map->indoor) text += ", over world.map";
  for (const Region& b : buildings) text += "; in the building of indoor obstacles within " + Corners(b);
  return text;
}

}  // namespace sanet::sim
