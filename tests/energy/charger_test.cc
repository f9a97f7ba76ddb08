// Chargers (docs/energy.md#chargers): a robot parked in a world charger's radius gains its power
// times the time, less what it draws, and stops at full; a mote at distance d from a robot's
// wireless charger gains what the efficiency model says, nothing beyond its range, and a dead
// mote comes back when its charge passes the revive level.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <optional>

#include "sim/assembly.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

constexpr double kIdleW = 0.5;

energy::EnergySpec Pack(double joules, double initial_fraction) {
  energy::EnergySpec e;
  e.battery_j = joules;
  e.initial_fraction = initial_fraction;
  return e;
}

sim::NodeSpec Parked(Pose2D at, double initial_fraction, std::optional<energy::WirelessCharger> charger = {}) {
  sim::NodeSpec n = Robot("robot", ModelKind::kDiffDrive, at, std::nullopt);
  n.energy = Pack(10000, initial_fraction);
  n.energy->drive = energy::DriveCosts{0.6, kIdleW, 0.01};
  n.energy->wireless_charger = charger;
  return n;
}

sim::NodeSpec Mote(Vec2 at, double initial_fraction) {
  sim::NodeSpec n = Robot("mote", ModelKind::kMote, {at.x, at.y, 0}, std::nullopt);
  n.energy = Pack(10, initial_fraction);
  return n;
}

struct After {
  double remaining_j, charged_j;
  std::map<std::string, double> used;
  std::optional<double> revived;
  bool charging = false;
};

After RunAndRead(sim::RunSpec spec, NodeId id) {
  sim::World world(std::move(spec), BuiltinRegistry());
  auto revived = std::make_shared<std::optional<double>>();
  Subscription keep = world.bus().On<sim::Revived>(sim::RunStage::kRecord, [revived, id](const sim::Revived& e) {
    if (e.node == id && !*revived) *revived = e.t;
  });
  world.Run({});
  const energy::NodeEnergy& e = *world.parts().batteries().Of(id);
  After a{e.remaining_j(), e.charged_j(), {}, *revived, e.Reading().charging};
  for (const auto& [component, joules] : e.Used()) a.used[component] = joules;
  return a;
}

TEST(Chargers, ARobotParkedInAChargersRadiusGainsItsPowerTimesTheTimeLessWhatItDraws) {
  sim::RunSpec spec = Spec(20, {Parked({1, 0, 0}, 0.5)});
  spec.chargers.push_back({{0, 0}, 1.5, 12});
  const After a = RunAndRead(spec, 0);
  EXPECT_NEAR(a.charged_j, 12 * 20, 1e-6);
  EXPECT_NEAR(a.remaining_j, 5000 + (12 - kIdleW) * 20, 1e-3);
  EXPECT_TRUE(a.charging);
}

TEST(Chargers, OutsideTheRadiusNothingComes) {
  sim::RunSpec spec = Spec(10, {Parked({2, 0, 0}, 0.5)});
  spec.chargers.push_back({{0, 0}, 1.5, 12});
  const After a = RunAndRead(spec, 0);
  EXPECT_DOUBLE_EQ(a.charged_j, 0);
  EXPECT_NEAR(a.remaining_j, 5000 - kIdleW * 10, 1e-3);
}

TEST(Chargers, ABatteryStopsChargingAtFull) {
  sim::RunSpec spec = Spec(20, {Parked({0, 0, 0}, 0.99)});
  spec.chargers.push_back({{0, 0}, 1, 100});
  const After a = RunAndRead(spec, 0);
  EXPECT_NEAR(a.remaining_j, 10000, 1e-6);
  EXPECT_NEAR(a.charged_j, 100 + kIdleW * 20, 1e-3);  // what it lacked, and what it drew meanwhile
  EXPECT_FALSE(a.charging);
}

TEST(Chargers, ALithiumIonPackChargesAsMuchAndStopsAtFullToo) {
  for (const double start : {0.5, 0.995}) {
    sim::NodeSpec robot = Parked({0, 0, 0}, start);
    robot.energy->source = energy::Chemistry::kLiIon;
    sim::RunSpec spec = Spec(20, {robot});
    spec.chargers.push_back({{0, 0}, 1, 12});
    const After a = RunAndRead(spec, 0);
    const double expected = std::min(10000.0, 10000 * start + (12 - kIdleW) * 20);
    EXPECT_NEAR(a.remaining_j, expected, 1e-3) << "from " << start;
    EXPECT_NEAR(a.charged_j, expected - 10000 * start + kIdleW * 20, 1e-3) << "from " << start;
  }
}

TEST(Chargers, AMoteAtDistanceDGainsWhatTheEfficiencyModelSays) {
  const energy::WirelessCharger charger{3, 5, 0.0036, 0.2316};
  for (double d : {0.5, 1.0, 2.0}) {
    const After a = RunAndRead(Spec(30, {Parked({0, 0, 0}, 1, charger), Mote({d, 0}, 0.2)}), 1);
    const double expected = 3 * 0.0036 / ((d + 0.2316) * (d + 0.2316)) * 30;
    // The robot settles on its wheels by a fraction of a millimetre: 1e-3 of the power.
    EXPECT_NEAR(a.charged_j, expected, 1e-3 * expected) << "at " << d << " m";
    EXPECT_NEAR(a.remaining_j, 2 + a.charged_j, 1e-9) << "at " << d << " m";
  }
}

TEST(Chargers, TheRobotPaysWhatItsChargerRadiatesAndNothingReachesBeyondItsRange) {
  const energy::WirelessCharger charger{3, 1.5, 0.0036, 0.2316};
  sim::RunSpec spec = Spec(10, {Parked({0, 0, 0}, 1, charger), Mote({2, 0}, 0.2)});
  EXPECT_DOUBLE_EQ(RunAndRead(spec, 1).charged_j, 0);
  EXPECT_DOUBLE_EQ(RunAndRead(spec, 0).used.at("wireless_charger"), 0);  // nobody to charge: it stays off
  spec.nodes[1].pose = {1, 0, 0};
  EXPECT_NEAR(RunAndRead(spec, 0).used.at("wireless_charger"), 3 * 10, 1e-6);
}

TEST(Chargers, ADeadMoteComesBackWhenItsChargePassesTheReviveLevel) {
  const energy::WirelessCharger charger{3, 5, 0.0036, 0.2316};
  sim::NodeSpec mote = Mote({0.5, 0}, 0);  // dead from the start: its charge is at the cutoff
  mote.energy->revive = 0.01;
  const double received_w = 3 * 0.0036 / ((0.5 + 0.2316) * (0.5 + 0.2316));
  const After a = RunAndRead(Spec(20, {Parked({0, 0, 0}, 1, charger), mote}), 1);
  ASSERT_TRUE(a.revived);
  EXPECT_NEAR(*a.revived, 0.01 * 10 / received_w, 1e-3 * *a.revived);  // the robot settles (above)
}

}  // namespace
}  // namespace sanet
