#include "sensors/surroundings.h"

namespace sanet::sensors {

// The crossing-number test: a ray from `p` towards +x crosses the boundary an odd number of
// times from inside.
bool Inside(const Region& region, Vec2 p) {
  if (region.size() < 3) return false;
  bool inside = false;
  for (std::size_t i = 0, j = region.size() - 1; i < region.size(); j = i++) {
    const Vec2 a = region[i], b = region[j];
    if ((a.y > p.y) == (b.y > p.y)) continue;
    const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
    if (p.x < x) inside = !inside;
  }
  return inside;
}

bool Surroundings::Denied(Vec2 p) const {
  for (const Region& r : gnss_denied)
    if (Inside(r, p)) return true;
  return false;
}

}  // namespace sanet::sensors
