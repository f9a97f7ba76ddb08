#include "scenario/scatter.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

namespace sanet::scenario {
namespace {

constexpr double kEdgeSigmas = 4;  // cluster centres are drawn this many sigmas beyond the region

// The scattered positions so far, in cells as wide as the separation, for nearness checks.
class Spacing {
 public:
  explicit Spacing(double gap) : gap_(gap), cell_(std::max(gap, 1e-3)) {}
  bool Clear(Vec2 p) const {
    if (gap_ <= 0) return true;
    const long long cx = Cell(p.x), cy = Cell(p.y);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto found = cells_.find(Key(cx + dx, cy + dy));
        if (found == cells_.end()) continue;
        for (Vec2 q : found->second)
          if (Norm(q - p) < gap_) return false;
      }
    return true;
  }
  void Add(Vec2 p) { cells_[Key(Cell(p.x), Cell(p.y))].push_back(p); }

 private:
  long long Cell(double v) const { return std::llround(std::floor(v / cell_)); }
  static long long Key(long long cx, long long cy) { return cx * 4000003LL + cy; }
  double gap_, cell_;
  std::unordered_map<long long, std::vector<Vec2>> cells_;
};

Vec2 UniformIn(const ScatterRegion& r, RandomStream& random) {
  return {r.min.x + (r.max.x - r.min.x) * random.Uniform(), r.min.y + (r.max.y - r.min.y) * random.Uniform()};
}

// Draws positions from `draw` until one lies in the region, fits and keeps its distance.
std::optional<Vec2> Place(const ScatterSettings& s, Spacing& spacing, const std::function<bool(Vec2)>& fits,
                          const std::function<Vec2()>& draw) {
  for (int attempt = 0; attempt < kScatterAttempts; ++attempt) {
    const Vec2 p = draw();
    if (s.region.Contains(p) && spacing.Clear(p) && fits(p)) {
      spacing.Add(p);
      return p;
    }
  }
  return std::nullopt;
}

Scattered ScatterUniform(const ScatterSettings& s, long long wanted, RandomStream& random, Spacing& spacing,
                         const std::function<bool(Vec2)>& fits) {
  Scattered out;
  out.wanted = wanted;
  for (long long i = 0; i < wanted; ++i) {
    const auto p = Place(s, spacing, fits, [&] { return UniformIn(s.region, random); });
    if (!p) return out.complete = false, out;
    out.positions.push_back(*p);
  }
  return out;
}

// Thomas: centres uniform over the region widened by kEdgeSigmas sigmas (so clusters near the edge
// are as dense as inside), a Poisson number of nodes around each; nodes outside the region are
// not part of the deployment.
Scattered ScatterClustered(const ScatterSettings& s, RandomStream& random, Spacing& spacing,
                           const std::function<bool(Vec2)>& fits) {
  ScatterRegion wide = s.region;
  const double edge = kEdgeSigmas * s.cluster_sigma;
  wide.min = {wide.min.x - edge, wide.min.y - edge};
  wide.max = {wide.max.x + edge, wide.max.y + edge};
  const long long parents =
      PoissonDraw(random, s.parent_density * (wide.max.x - wide.min.x) * (wide.max.y - wide.min.y));
  Scattered out;
  for (long long c = 0; c < parents; ++c) {
    const Vec2 centre = UniformIn(wide, random);
    const long long children = PoissonDraw(random, s.per_cluster);
    const auto around = [&] {
      return centre + Vec2{s.cluster_sigma * random.Gaussian(0, 1), s.cluster_sigma * random.Gaussian(0, 1)};
    };
    for (long long i = 0; i < children; ++i) {
      std::optional<Vec2> first = around();
      if (!s.region.Contains(*first)) continue;  // outside the window: not deployed
      ++out.wanted;
      // Where the process put it, or, if that spot is taken, elsewhere around the same centre.
      const auto p =
          Place(s, spacing, fits, [&] { return first ? std::exchange(first, std::nullopt).value() : around(); });
      if (!p) return out.complete = false, out;
      out.positions.push_back(*p);
    }
  }
  return out;
}

}  // namespace

bool ScatterRegion::Contains(Vec2 p) const {
  if (p.x < min.x || p.x > max.x || p.y < min.y || p.y > max.y) return false;
  if (polygon.size() < 3) return true;
  bool inside = false;  // even-odd rule: crossings of a ray towards +x
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x)) inside = !inside;
  }
  return inside;
}

double ScatterRegion::Area() const {
  if (polygon.size() < 3) return (max.x - min.x) * (max.y - min.y);
  double twice = 0;  // the shoelace formula
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    twice += polygon[j].x * polygon[i].y - polygon[i].x * polygon[j].y;
  return std::abs(twice) / 2;
}

long long PoissonDraw(RandomStream& random, double mean) {
  constexpr double kPiece = 500;  // exp(-500) is still a normal double
  long long total = 0;
  for (double left = mean; left > 0; left -= kPiece) {
    const double piece = std::min(left, kPiece);
    // Inversion: walk up the distribution function until it passes a uniform draw.
    const double u = random.Uniform();
    double p = std::exp(-piece), cdf = p;
    long long k = 0;
    while (u > cdf && p > 0) {
      ++k;
      p *= piece / k;
      cdf += p;
    }
    total += k;
  }
  return total;
}

Scattered Scatter(const ScatterSettings& s, std::uint64_t run_seed, double body_gap,
                  const std::function<bool(Vec2)>& fits) {
  RandomStream random(s.seed.value_or(run_seed), "scatter/" + s.name);
  Spacing spacing(std::max(s.min_separation, body_gap));
  switch (s.distribution) {
    case ScatterDistribution::kUniform:
      return ScatterUniform(s, s.count.value_or(0), random, spacing, fits);
    case ScatterDistribution::kPoisson:
      return ScatterUniform(s, PoissonDraw(random, s.density.value_or(0) * s.region.Area()), random, spacing, fits);
    case ScatterDistribution::kClustered:
      return ScatterClustered(s, random, spacing, fits);
  }
  return {};
}

}  // namespace sanet::scenario
