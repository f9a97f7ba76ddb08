// What sensors may know of the world beyond bodies: where it lies on the Earth (a datum for
// satellite fixes) and where satellites cannot be heard (indoors, or regions a scenario lists).
// The run builds it from its scenario's world (sim/surroundings_of.h); each sensor sees it
// through its Mount.
#pragma once

#include <optional>
#include <vector>

#include "sanet/geometry.h"

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

struct Surroundings {
  std::optional<GeoDatum> datum;    // none: the scenario gave no world.datum
  std::vector<Region> gnss_denied;  // no satellite fix inside any of them
  bool Denied(Vec2 p) const;
};

}  // namespace sanet::sensors
