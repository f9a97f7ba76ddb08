// Scattered nodes: drawn from the run's seed (or the item's own), in their region, apart, out of
// obstacles; Poisson counts with Poisson's mean and variance; Thomas clusters; an impossible
// request refused at its line.
#include "scenario/scatter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "scenario/scenario_loader.h"

namespace sanet {
namespace {

using scenario::Scatter;
using scenario::ScatterDistribution;
using scenario::ScatterSettings;

// The scenario `text` in a file of its own, loaded with `sets`.
scenario::Scenario Load(const std::string& text, std::vector<std::string> sets = {}) {
  const std::string path = ::testing::TempDir() + "/scatter_test.yaml";
  std::ofstream(path) << text;
  return scenario::LoadScenario(path, sets);
}

constexpr const char* kField = R"(duration: 5
world:
  obstacles:
    - box: {center: [50, 50], size: [30, 30, 1]}
nodes:
  - {name: sink, model: mote, pose: [10, 10, 0]}
  - scatter: {name: m, count: 60, region: {min: [0, 0], max: [100, 100]}, min_separation: 6}
    model: mote
)";

std::vector<Vec2> Positions(const scenario::Scenario& sc, const std::string& prefix) {
  std::vector<Vec2> out;
  for (const sim::NodeSpec& n : sc.run.nodes)
    if (n.name.rfind(prefix, 0) == 0) out.push_back(n.pose.position());
  return out;
}

TEST(Scatter, PositionsComeFromTheRunsSeedAndKeepTheirDistanceInTheirRegion) {
  const scenario::Scenario one = Load(kField), again = Load(kField), other = Load(kField, {"seed=2"});
  const std::vector<Vec2> a = Positions(one, "m"), b = Positions(again, "m"), c = Positions(other, "m");
  ASSERT_EQ(a.size(), 60u);
  EXPECT_EQ(one.run.nodes[1].name, "m0");
  EXPECT_EQ(one.run.nodes.back().name, "m59");
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x, b[i].x);
    EXPECT_EQ(a[i].y, b[i].y);
  }
  int moved = 0;
  for (std::size_t i = 0; i < a.size(); ++i) moved += a[i].x != c[i].x;
  EXPECT_EQ(moved, 60) << "another seed, another deployment";
  for (const auto& positions : {a, c})
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const Vec2 p = positions[i];
      EXPECT_TRUE(p.x >= 0 && p.x <= 100 && p.y >= 0 && p.y <= 100);
      EXPECT_FALSE(std::abs(p.x - 50) < 15 && std::abs(p.y - 50) < 15) << "inside the box";
      EXPECT_GE(Norm(p - Vec2{10, 10}), 0.05) << "on the sink";
      for (std::size_t j = 0; j < i; ++j) EXPECT_GE(Norm(p - positions[j]), 6.0);
    }
}

TEST(Scatter, AnItemsOwnSeedGivesTheSameDeploymentInEveryRun) {
  std::string text = kField;
  text.replace(text.find("min_separation: 6}"), 18, "min_separation: 6, seed: 77}");
  const std::vector<Vec2> a = Positions(Load(text), "m"), b = Positions(Load(text, {"seed=9"}), "m");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].x, b[i].x);
}

TEST(Scatter, APolygonHoldsItsNodes) {
  ScatterSettings s;
  s.name = "t";
  s.count = 500;
  s.region.polygon = {{0, 0}, {10, 0}, {0, 10}};  // a right triangle
  s.region.min = {0, 0};
  s.region.max = {10, 10};
  EXPECT_DOUBLE_EQ(s.region.Area(), 50);
  const scenario::Scattered drawn = Scatter(s, 3, 0, [](Vec2) { return true; });
  ASSERT_EQ(drawn.positions.size(), 500u);
  for (Vec2 p : drawn.positions) EXPECT_LE(p.x + p.y, 10 + 1e-9);
}

TEST(Scatter, PoissonCountsHavePoissonsMeanAndVariance) {
  ScatterSettings s;
  s.name = "p";
  s.distribution = ScatterDistribution::kPoisson;
  s.density = 0.002;  // 20 nodes on 100 m x 100 m on average
  s.region.max = {100, 100};
  double sum = 0, squares = 0;
  const int seeds = 4000;
  for (int seed = 0; seed < seeds; ++seed) {
    const double n = Scatter(s, seed, 0, [](Vec2) { return true; }).positions.size();
    sum += n, squares += n * n;
  }
  const double mean = sum / seeds, variance = squares / seeds - mean * mean;
  EXPECT_NEAR(mean, 20, 0.25);
  EXPECT_NEAR(variance, 20, 1.5);
  RandomStream large(1, "large");
  double big = 0;
  for (int i = 0; i < 200; ++i) big += scenario::PoissonDraw(large, 5000);
  EXPECT_NEAR(big / 200, 5000, 15) << "means beyond exp's range are drawn in pieces";
}

TEST(Scatter, ThomasClustersGatherNodesAroundCentres) {
  ScatterSettings s;
  s.name = "c";
  s.distribution = ScatterDistribution::kClustered;
  s.parent_density = 0.0005;  // 5 centres on 100 m x 100 m
  s.per_cluster = 8;
  s.cluster_sigma = 3;
  s.region.max = {100, 100};
  double total = 0, nearest_clustered = 0, nearest_uniform = 0;
  const auto mean_nearest = [](const std::vector<Vec2>& points) {
    double sum = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      double best = 1e9;
      for (std::size_t j = 0; j < points.size(); ++j)
        if (i != j) best = std::min(best, Norm(points[i] - points[j]));
      sum += best;
    }
    return points.size() > 1 ? sum / points.size() : 0.0;
  };
  const int seeds = 400;
  for (int seed = 0; seed < seeds; ++seed) {
    const auto drawn = Scatter(s, seed, 0, [](Vec2) { return true; }).positions;
    total += drawn.size();
    ScatterSettings u;
    u.name = "u";
    u.count = static_cast<long long>(std::max<std::size_t>(drawn.size(), 2));
    u.region.max = {100, 100};
    nearest_clustered += mean_nearest(drawn);
    nearest_uniform += mean_nearest(Scatter(u, seed, 0, [](Vec2) { return true; }).positions);
  }
  EXPECT_NEAR(total / seeds, 40, 40 * 0.08) << "centres x nodes per centre, inside the region";
  EXPECT_LT(nearest_clustered, 0.5 * nearest_uniform) << "clustered nodes stand nearer each other";
}

TEST(Scatter, AnImpossibleRequestIsRefusedAtItsLineSayingHowManyFitted) {
  std::string text = kField;
  text.replace(text.find("count: 60"), 9, "count: 900");
  try {
    Load(text);
    FAIL() << "900 nodes 6 m apart in 100 m x 100 m less a box";
  } catch (const scenario::ScenarioError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(":7:"), std::string::npos) << what;
    EXPECT_NE(what.find("nodes[1].scatter"), std::string::npos) << what;
    EXPECT_NE(what.find(" of 900 nodes fitted"), std::string::npos) << what;
  }
  for (const auto& [change, message] : std::vector<std::pair<std::string, std::string>>{
           {"nodes.m.scatter.distribution=poisson", "applies to `distribution: uniform` only"},
           {"nodes.m.scatter.region={min: [5, 5], max: [1, 1]}", "must be above and to the right"},
           {"nodes.m.scatter.region={polygon: [[0, 0], [1, 1]]}", "three corners"}}) {
    try {
      Load(kField, {change});
      ADD_FAILURE() << change;
    } catch (const scenario::ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace sanet
