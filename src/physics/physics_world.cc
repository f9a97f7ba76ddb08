#include "physics/physics_world.h"

namespace sanet::physics {

std::unique_ptr<PhysicsWorld> CreatePhysicsWorld(const WorldSettings& settings) {
  return settings.engine == Engine::k2d ? CreateBox2dWorld(settings) : CreateOdeWorld(settings);
}

}  // namespace sanet::physics
