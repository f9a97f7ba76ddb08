// What sensors may know of the world beyond bodies: where it lies on the Earth (a datum for
// satellite fixes) and where satellites cannot be heard (indoors, or regions a scenario lists).
// The run builds it from its scenario's world (sim/surroundings_of.h); each sensor sees it
// through its Mount.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/rgb.h"
#include "physics/physics_world.h"
#include "sanet/geometry.h"
#include "sanet/message.h"

namespace sanet::sensors {

// The world's origin on the WGS 84 ellipsoid. The world's x points east, y north and z up (the
// east-north-up frame REP 105 gives a map), and its ground lies at the datum's altitude.
struct GeoDatum {
  double latitude = 0;   // degrees, positive north
  double longitude = 0;  // degrees, positive east
  double altitude = 0;   // m above the ellipsoid
};

// A region of the ground as a simple polygon, its corners in order (either way round).
using Region = std::vector<Vec2>;

// Whether `p` lies inside `region` (on an edge counts as inside half the time, as crossing
// counts go: regions are areas, not lines).
bool Inside(const Region& region, Vec2 p);

// What a camera sees of the world: the ground, the sky, the obstacles (still), and the nodes'
// bodies where they are now.
struct SceneBox {
  physics::Vec3 center, size;  // m; size: length along yaw, width, height
  double yaw = 0;              // rad
  Rgb color;
};
struct SceneBody {
  NodeId node = 0;
  bool box = true;                           // else an upright cylinder of `radius`
  double length = 0, width = 0, radius = 0;  // m
  double height = 0, base = 0;               // m: its height, and its bottom above the ground
  Pose2D pose;                               // of its centre
  Rgb color;
};
struct Scenery {
  Rgb ground, sky;
  std::vector<SceneBox> boxes;
  // Every node's body as it is now (set by the run once the bodies exist; empty before).
  std::function<void(std::vector<SceneBody>&)> bodies;
};

struct Surroundings {
  std::optional<GeoDatum> datum;    // none: the scenario gave no world.datum
  std::vector<Region> gnss_denied;  // no satellite fix inside any of them
  Scenery scenery;
  bool Denied(Vec2 p) const;
};

}  // namespace sanet::sensors
