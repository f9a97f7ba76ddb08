// What stands between two antennas: the length of a segment inside walls and boxes (with their
// heights and yaw) against the geometry worked out by hand, the multi-wall loss against its
// formula (a loss per obstacle crossed plus a loss per metre inside), and the grid's answers
// against asking every obstacle.
#include "net/obstacle_crossings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sanet::net {
namespace {

using physics::StaticBox;
using physics::Vec3;

// A wall from (x, -3) to (x, 3): 6 m long, `thick` m thick, `height` m high, standing on the floor.
RadioObstacle WallAcrossX(double x, double thick, double height, double loss_db, double per_m = 0) {
  return {StaticBox{{x, 0, height / 2}, {6, thick, height}, M_PI / 2}, loss_db, per_m};
}

TEST(ObstacleCrossings, OneWallAddsItsLossAndItsDepthTimesTheLossPerMetre) {
  const ObstacleCrossings walls({WallAcrossX(5, 0.2, 2.5, 10, 5)});
  const auto crossed = walls.Crossings({0, 0, 1}, {10, 0, 1});
  ASSERT_EQ(crossed.size(), 1u);
  EXPECT_NEAR(crossed[0].length, 0.2, 1e-9);
  EXPECT_NEAR(walls.LossDb({0, 0, 1}, {10, 0, 1}), 10 + 5 * 0.2, 1e-9);
  EXPECT_EQ(walls.LossDb({0, 0, 1}, {4, 0, 1}), 0) << "both ends before the wall";
}

TEST(ObstacleCrossings, TwoWallsAddTwice) {
  const ObstacleCrossings walls({WallAcrossX(3, 0.3, 2.5, 12), WallAcrossX(7, 0.3, 2.5, 12)});
  EXPECT_NEAR(walls.LossDb({0, 1, 1}, {10, -1, 1}), 24, 1e-9);
  EXPECT_NEAR(walls.LossDb({0, 1, 1}, {5, 1, 1}), 12, 1e-9);
}

// A map's wall cut into pieces: two boxes side by side across it (x 5.0-5.05 and 5.05-5.1),
// and a third piece 1 m on.
TEST(ObstacleCrossings, PiecesCrossedOneAfterAnotherAreOneWall) {
  const auto piece = [](double x) {
    RadioObstacle o{StaticBox{{x, 0, 1.25}, {0.05, 6, 2.5}, 0}, 10};
    o.piece = true, o.joined_within = 0.025;
    return o;
  };
  const ObstacleCrossings walls({piece(5.025), piece(5.075), piece(6.025)});
  EXPECT_NEAR(walls.LossDb({0, 0, 1}, {5.5, 0, 1}), 10, 1e-9) << "two touching pieces: one wall";
  EXPECT_NEAR(walls.LossDb({0, 0, 1}, {10, 0, 1}), 20, 1e-9) << "the third, 0.9 m beyond: another";
  EXPECT_NEAR(walls.LossDb({0, -2, 1}, {10, 3, 1}), 20, 1e-9) << "slanted: still two walls";
  const ObstacleCrossings apart({WallAcrossX(5.025, 0.05, 2.5, 10), WallAcrossX(5.075, 0.05, 2.5, 10)});
  EXPECT_NEAR(apart.LossDb({0, 0, 1}, {5.5, 0, 1}), 20, 1e-9) << "walls that are not pieces count each";
}

TEST(ObstacleCrossings, ASegmentOverALowWallIsNotAttenuated) {
  const ObstacleCrossings walls({WallAcrossX(5, 0.2, 1.0, 10)});
  // From 0.2 m up to 2.0 m up: at the wall (half way) the segment is 1.1 m up, over its 1 m.
  EXPECT_EQ(walls.LossDb({0, 0, 0.2}, {10, 0, 2.0}), 0);
  // Lower at both ends, it passes through.
  EXPECT_NEAR(walls.LossDb({0, 0, 0.2}, {10, 0, 0.5}), 10, 1e-9);
}

TEST(ObstacleCrossings, AnObliqueSegmentCrossesMoreOfTheWall) {
  const double thick = 0.25;
  // At 45 degrees to the wall's normal, through its middle: thick * sqrt(2) inside.
  const auto crossed = ObstacleCrossings({WallAcrossX(5, thick, 3, 0)}).Crossings({3, -2, 1}, {7, 2, 1});
  ASSERT_EQ(crossed.size(), 1u);
  EXPECT_NEAR(crossed[0].length, thick * std::sqrt(2.0), 1e-9);
}

TEST(ObstacleCrossings, AYawedBoxIsCrossedWhereItStands) {
  // A 2 m x 1 m box turned by 30 degrees; a segment along its long axis crosses all 2 m of it.
  const double yaw = M_PI / 6;
  const RadioObstacle box{StaticBox{{10, 10, 0.5}, {2, 1, 1}, yaw}, 3, 0};
  const Vec3 a{10 - 5 * std::cos(yaw), 10 - 5 * std::sin(yaw), 0.5};
  const Vec3 b{10 + 5 * std::cos(yaw), 10 + 5 * std::sin(yaw), 0.5};
  EXPECT_NEAR(LengthInside(box.box, a, b), 2, 1e-9);
  EXPECT_EQ(LengthInside(box.box, {0, 0, 0.5}, {20, 0, 0.5}), 0) << "far from it";
}

TEST(ObstacleCrossings, TheGridFindsWhatAskingEveryObstacleFinds) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> where(-40, 40), size(0.1, 6), turn(-M_PI, M_PI), up(0, 3);
  std::vector<RadioObstacle> obstacles;
  for (int i = 0; i < 150; ++i) {
    const double h = up(random) + 0.1;
    obstacles.push_back(
        {StaticBox{{where(random), where(random), h / 2}, {size(random), size(random), h}, turn(random)}, 1, 0});
  }
  const ObstacleCrossings grid(obstacles, 4.0);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 a{where(random), where(random), up(random)};
    const Vec3 b = k % 10 == 0 ? a : Vec3{where(random), where(random), up(random)};
    std::vector<std::size_t> expected;
    for (std::size_t i = 0; i < obstacles.size(); ++i)
      if (LengthInside(obstacles[i].box, a, b) > 0) expected.push_back(i);
    std::vector<std::size_t> found;
    for (const Crossing& c : grid.Crossings(a, b)) found.push_back(c.obstacle);
    ASSERT_EQ(found, expected) << "segment " << k;
  }
}

TEST(ObstacleCrossings, NoObstaclesNoLoss) {
  const ObstacleCrossings none({});
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(none.LossDb({0, 0, 0}, {100, 100, 0}), 0);
}

}  // namespace
}  // namespace sanet::net
