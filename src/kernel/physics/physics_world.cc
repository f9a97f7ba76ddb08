#include "physics/physics_world.h"

#include <algorithm>
#include <cmath>

namespace sanet::physics {

std::vector<double> PhysicsWorld::cast_rays(const std::vector<Ray>& rays, double max_range, const Body* ignore) const {
  std::vector<double> ranges;
  ranges.reserve(rays.size());
  for (const Ray& r : rays) ranges.push_back(cast_ray(r.origin, r.direction, max_range, ignore));
  return ranges;
}

double DistanceFromAbove(Vec2 p, const StaticBox& box) {
  const double dx = p.x - box.center.x, dy = p.y - box.center.y;
  const double c = std::cos(box.yaw), s = std::sin(box.yaw);
  const double along = c * dx + s * dy, across = -s * dx + c * dy;
  const double out_along = std::max(0.0, std::fabs(along) - box.size.x / 2);
  const double out_across = std::max(0.0, std::fabs(across) - box.size.y / 2);
  return std::hypot(out_along, out_across);
}

std::array<Vec2, 4> FootprintCorners(const StaticBox& box) {
  const double c = std::cos(box.yaw), s = std::sin(box.yaw), hx = box.size.x / 2, hy = box.size.y / 2;
  std::array<Vec2, 4> corners;
  int i = 0;
  for (const auto& [u, v] : {std::pair{hx, hy}, {-hx, hy}, {-hx, -hy}, {hx, -hy}})
    corners[i++] = {box.center.x + c * u - s * v, box.center.y + s * u + c * v};
  return corners;
}

std::unique_ptr<PhysicsWorld> CreatePhysicsWorld(const WorldSettings& settings) {
  return settings.engine == Engine::k2d ? CreateBox2dWorld(settings) : CreateOdeWorld(settings);
}

}  // namespace sanet::physics
