// The walls in the radio: the materials' slab losses against ITU-R P.2040-1's formula worked out
// independently (the values below), and the ns-3 loss chain (the scenario's path loss, then the
// walls) against the multi-wall formula: received power = transmit power − log-distance loss −
// the loss of each wall crossed, with antennas raised by their heights and a pair's loss kept
// only while neither end moves.
#include <gtest/gtest.h>
#include <ns3/constant-position-mobility-model.h>
#include <ns3/node.h>

#include <cmath>
#include <memory>

#include "net/obstacle_loss_model.h"
#include "net/path_loss.h"
#include "net/wall_materials.h"

namespace sanet::net {
namespace {

using physics::StaticBox;

// P.2040-1 Table 3 and its single-layer slab at normal incidence, computed apart from the code
// (complex arithmetic by hand in a script: docs/network.md#walls tabulates the same numbers).
TEST(WallMaterials, SlabLossesAreP2040sAtTheRadiosBands) {
  struct Case {
    Material material;
    double thickness, ghz, loss_db;
  };
  for (const Case& c : {Case{Material::kConcrete, 0.2, 2.412, 11.05}, Case{Material::kConcrete, 0.3, 5.18, 27.75},
                        Case{Material::kBrick, 0.2, 2.412, 7.36}, Case{Material::kBrick, 0.1, 5.18, 4.28},
                        Case{Material::kWood, 0.04, 2.412, 0.61}, Case{Material::kWood, 0.2, 5.18, 6.60},
                        Case{Material::kGlass, 0.01, 2.412, 3.09}, Case{Material::kGlass, 0.01, 5.18, 0.96}})
    EXPECT_NEAR(SlabLossDb(c.material, c.thickness, c.ghz * 1e9), c.loss_db, 0.01)
        << MaterialName(c.material) << " " << c.thickness << " m at " << c.ghz << " GHz";
  EXPECT_EQ(SlabLossDb(Material::kNone, 0.3, 2.412e9), 0);
  EXPECT_EQ(SlabLossDb(Material::kMetal, 0.002, 2.412e9), kMaxSlabLossDb) << "2 mm of sheet metal";
  // Concrete's conductivity grows with frequency (c·f^d): 5 GHz loses more than 2.4 GHz.
  EXPECT_GT(SlabLossDb(Material::kConcrete, 0.2, 5.18e9), SlabLossDb(Material::kConcrete, 0.2, 2.412e9) + 5);
}

TEST(WallMaterials, NamesReadBack) {
  for (const std::string& name : MaterialNames()) EXPECT_EQ(MaterialName(*MaterialNamed(name)), name);
  EXPECT_FALSE(MaterialNamed("plaster"));
}

// A wall across the x axis at `x`, 6 m long.
RadioObstacle WallAt(double x, double loss_db, double height = 2.5) {
  return {StaticBox{{x, 0, height / 2}, {6, 0.2, height}, M_PI / 2}, loss_db, 0};
}

struct Chain {
  ns3::Ptr<ns3::PropagationLossModel> loss;
  ns3::Ptr<ObstacleLossModel> walls = ns3::CreateObject<ObstacleLossModel>();
  ns3::Ptr<ns3::Node> a = ns3::CreateObject<ns3::Node>(), b = ns3::CreateObject<ns3::Node>();
  ns3::Ptr<ns3::ConstantPositionMobilityModel> at_a = ns3::CreateObject<ns3::ConstantPositionMobilityModel>(),
                                               at_b = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  explicit Chain(std::vector<RadioObstacle> obstacles) : loss(PathLoss(NetworkSpec{})) {
    walls->SetObstacles(std::make_shared<const ObstacleCrossings>(std::move(obstacles)));
    LastOf(loss)->SetNext(walls);
    a->AggregateObject(at_a);
    b->AggregateObject(at_b);
  }
  double Received(ns3::Vector from, ns3::Vector to) {
    at_a->SetPosition(from);
    at_b->SetPosition(to);
    return loss->CalcRxPower(16, at_a, at_b);
  }
};

// The default log-distance model: 46.6777 dB at 1 m, exponent 3.
double PathLossDb(double d) { return 46.6777 + 30 * std::log10(d); }

TEST(ObstacleLossModel, ReceivedPowerIsThePathLossLessEachWallCrossed) {
  Chain chain({WallAt(3, 7.5), WallAt(6, 11.05)});
  EXPECT_NEAR(chain.Received({0, 0, 0.1}, {2, 0, 0.1}), 16 - PathLossDb(2), 1e-9) << "no wall between";
  EXPECT_NEAR(chain.Received({0, 0, 0.1}, {4, 1, 0.1}), 16 - PathLossDb(std::hypot(4, 1)) - 7.5, 1e-9) << "one wall";
  EXPECT_NEAR(chain.Received({0, 0, 0.1}, {8, -2, 0.1}), 16 - PathLossDb(std::hypot(8, 2)) - 7.5 - 11.05, 1e-9)
      << "two walls";
  EXPECT_NEAR(chain.Received({8, -2, 0.1}, {0, 0, 0.1}), 16 - PathLossDb(std::hypot(8, 2)) - 7.5 - 11.05, 1e-9)
      << "the other way";
}

TEST(ObstacleLossModel, AntennasRaisedOverALowWallAreNotAttenuated) {
  Chain chain({WallAt(5, 12, 1.0)});
  EXPECT_NEAR(chain.Received({0, 0, 0.1}, {10, 0, 0.1}), 16 - PathLossDb(10) - 12, 1e-9) << "under the wall's top";
  chain.walls->SetAntennaHeight(chain.a->GetId(), 1.5);
  chain.walls->SetAntennaHeight(chain.b->GetId(), 1.5);
  // The path loss keeps the nodes' own distance: the heights raise the segment only.
  EXPECT_NEAR(chain.Received({0, 0, 0.1}, {10, 0, 0.1}), 16 - PathLossDb(10), 1e-9) << "over it at 1.6 m";
}

TEST(ObstacleLossModel, APairsLossIsKeptWhileNeitherEndMoves) {
  Chain chain({WallAt(5, 12)});
  for (int i = 0; i < 5; ++i) chain.Received({0, 0, 0.1}, {10, 0, 0.1});
  EXPECT_EQ(chain.walls->counters().asked, 5u);
  EXPECT_EQ(chain.walls->counters().walked, 1u);
  EXPECT_NEAR(chain.Received({0, 0, 0.1}, {4, 0, 0.1}), 16 - PathLossDb(4), 1e-9) << "moved in front of the wall";
  EXPECT_NEAR(chain.Received({0, 0, 0.1}, {10, 0, 0.1}), 16 - PathLossDb(10) - 12, 1e-9) << "and back behind it";
  EXPECT_EQ(chain.walls->counters().walked, 3u);
}

}  // namespace
}  // namespace sanet::net
