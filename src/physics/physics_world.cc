#include "physics/physics_world.h"

namespace sanet::physics {

std::vector<double> PhysicsWorld::cast_rays(const std::vector<Ray>& rays, double max_range, const Body* ignore) const {
  std::vector<double> ranges;
  ranges.reserve(rays.size());
  for (const Ray& r : rays) ranges.push_back(cast_ray(r.origin, r.direction, max_range, ignore));
  return ranges;
}

std::unique_ptr<PhysicsWorld> CreatePhysicsWorld(const WorldSettings& settings) {
  return settings.engine == Engine::k2d ? CreateBox2dWorld(settings) : CreateOdeWorld(settings);
}

}  // namespace sanet::physics
