// Nodes scattered over a region, drawn from a seed (a scenario's `scatter` item,
// docs/scenario.md#scatter): a given number uniformly, a Poisson number (the count itself drawn
// from the density), or a Thomas cluster process (M. Thomas, "A generalization of Poisson's
// binomial limit for use in ecology", Biometrika 36, 1949: parents as a Poisson process, each with
// a Poisson number of children displaced by a Gaussian). Every position keeps the separation
// asked for from the others and whatever `fits` refuses (obstacles, nodes placed before); one
// that cannot be placed after kAttempts draws ends the scattering, and the result says how many
// fitted.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/random_stream.h"
#include "sanet/geometry.h"

namespace sanet::scenario {

// A rectangle, or a polygon when `polygon` has three corners or more.
struct ScatterRegion {
  Vec2 min{0, 0}, max{0, 0};  // the bounding box (of the polygon, if one)
  std::vector<Vec2> polygon;
  bool Contains(Vec2 p) const;
  double Area() const;
};

enum class ScatterDistribution { kUniform, kPoisson, kClustered };

struct ScatterSettings {
  std::string name;
  ScatterDistribution distribution = ScatterDistribution::kUniform;
  std::optional<long long> count;  // uniform
  std::optional<double> density;   // poisson: nodes per m²
  ScatterRegion region;
  double min_separation = 0;          // m between scattered nodes' positions
  std::optional<std::uint64_t> seed;  // instead of the run's
  double parent_density = 0;          // clustered: cluster centres per m²
  double per_cluster = 0;             // clustered: mean nodes per cluster
  double cluster_sigma = 0;           // clustered: m, each axis of a node's offset from its centre
};

struct Scattered {
  std::vector<Vec2> positions;
  long long wanted = 0;  // what the distribution asked for (drawn, for poisson and clustered)
  bool complete = true;  // false: a position could not be placed; `positions` holds those that fitted
};

constexpr int kScatterAttempts = 1000;  // draws for one position before it is given up

// `fits(p)`: whether a body of the item's model may stand at p (obstacles, earlier nodes);
// `body_gap`: the least distance between two of the item's own nodes for their bodies to clear.
Scattered Scatter(const ScatterSettings& s, std::uint64_t run_seed, double body_gap,
                  const std::function<bool(Vec2)>& fits);

// A Poisson variate of mean `mean` (inversion, in pieces of mean 500 at most: exact at any mean).
long long PoissonDraw(RandomStream& random, double mean);

}  // namespace sanet::scenario
