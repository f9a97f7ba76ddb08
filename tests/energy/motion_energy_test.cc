// Motion energy (docs/energy.md#motion), on either physics engine: a robot that accelerates spends
// at least its kinetic energy over the drive's efficiency; a parked robot spends only the drive's
// idle power; the energy grows with the distance driven, by the rolling resistance's work; sensors
// draw their power while the node is on.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sim/assembly.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

class MotionEnergy : public ::testing::TestWithParam<physics::Engine> {};

constexpr double kIdleW = 0.5, kEfficiency = 0.6, kRolling = 0.01, kGravity = 9.81;

sim::NodeSpec Driving(double vx) {
  sim::NodeSpec n =
      Robot("r", ModelKind::kDiffDrive, {0, 0, 0},
            UseController("constant_velocity", {{"vx", Scalar(vx)}, {"vy", Scalar(0)}, {"omega", Scalar(0)}}));
  energy::EnergySpec e;
  e.battery_j = 1e6;
  e.drive = energy::DriveCosts{kEfficiency, kIdleW, kRolling};
  n.energy = e;
  return n;
}

double Mass(const sim::NodeSpec& n) { return n.model.diffdrive.body_mass + 2 * n.model.diffdrive.wheel_mass; }

struct Spent {
  std::map<std::string, double> used;
  double distance = 0;
};

Spent Drive(sim::NodeSpec robot, double seconds) {
  sim::World world(On(MotionEnergy::GetParam(), Spec(seconds, {std::move(robot)})), BuiltinRegistry());
  world.Run({});
  Spent s;
  for (const auto& [component, joules] : world.parts().batteries().Of(0)->Used()) s.used[component] = joules;
  s.distance = world.model(0).body().pose().x;
  return s;
}

TEST_P(MotionEnergy, ARobotThatAcceleratesSpendsAtLeastItsKineticEnergyOverTheEfficiency) {
  const double v = 0.5, seconds = 2;
  const sim::NodeSpec robot = Driving(v);
  const Spent s = Drive(robot, seconds);
  const double kinetic = 0.5 * Mass(robot) * v * v;
  const double motion = s.used.at("motion") - kIdleW * seconds;
  EXPECT_GE(motion, kinetic / kEfficiency);
  // ... and not wildly more: the kinetic energy and a second or two of rolling.
  EXPECT_LT(motion, 3 * (kinetic + kRolling * Mass(robot) * kGravity * s.distance) / kEfficiency);
}

TEST_P(MotionEnergy, AParkedRobotSpendsOnlyItsDrivesIdlePower) {
  const double seconds = 5;
  const Spent s = Drive(Driving(0), seconds);
  EXPECT_NEAR(s.used.at("motion"), kIdleW * seconds, 1e-6);
  EXPECT_DOUBLE_EQ(s.used.at("sensors"), 0);
}

TEST_P(MotionEnergy, TheEnergyGrowsWithTheDistanceDrivenByTheRollingResistancesWork) {
  const double v = 0.5;
  const sim::NodeSpec robot = Driving(v);
  const Spent shorter = Drive(robot, 6), longer = Drive(robot, 12);
  const double extra_m = longer.distance - shorter.distance;
  ASSERT_NEAR(extra_m, v * 6, 0.3);
  const double extra_j = (longer.used.at("motion") - kIdleW * 12) - (shorter.used.at("motion") - kIdleW * 6);
  // The drive wheels carry three quarters of the weight; the caster, which rolls freely, the rest.
  const double rolling_j = kRolling * 0.75 * Mass(robot) * kGravity * extra_m / kEfficiency;
  EXPECT_NEAR(extra_j, rolling_j, 0.05 * rolling_j);
}

TEST_P(MotionEnergy, SensorsDrawTheirPowerWhileTheNodeIsOn) {
  sim::NodeSpec robot = Driving(0);
  robot.model.sensors.at("laser").power_w = 2;
  const Spent s = Drive(robot, 4);
  EXPECT_NEAR(s.used.at("sensors"), 8, 1e-6);
}

TEST_P(MotionEnergy, EachReadingOfACostlySensorCostsItsEnergy) {
  sim::NodeSpec robot = Driving(0);
  robot.controller = UseController("waypoint", {{"waypoints", Table({{100, 0}})}});  // reads its pose every step
  robot.model.sensors.at("ground_truth").energy_j = 0.01;
  const double seconds = 5, rate = robot.controller->rate;
  const Spent s = Drive(robot, seconds);
  // A reading at every control step, t = 0 to 5 s inclusive.
  EXPECT_NEAR(s.used.at("sensors"), 0.01 * (seconds * rate + 1), 1e-9);
}

// When a drive's work is drawn depends on the physics steps alone: not on who watches the world
// (an observer hears every step's end) nor on where a script cuts the run.
TEST_P(MotionEnergy, WatchingOrCuttingTheRunChangesNoJoule) {
  // The charge at every sample (each 0.0125 s, between physics steps' ends), watched or not.
  const auto samples = [](int how) {
    sim::RunSpec spec = On(MotionEnergy::GetParam(), Spec(3, {Driving(0.7)}));
    spec.energy_interval = 0.0125;
    sim::World world(std::move(spec), BuiltinRegistry());
    auto charges = std::make_shared<std::vector<double>>();
    Subscription keep = world.bus().On<sim::EnergySampled>(
        sim::RunStage::kRecord,
        [charges](const sim::EnergySampled& e) { charges->push_back(e.levels.at(0).battery.remaining_j); });
    if (how == 1) world.Observe([](const sim::WorldSnapshot&) {});
    if (how == 2) {
      world.Start({});
      for (double t = 0.0137; t < 3; t += 0.0137) world.RunUntil(t);
      world.RunUntil(3);
      world.Finish();
    } else {
      world.Run({});
    }
    return *charges;
  };
  const std::vector<double> alone = samples(0);
  ASSERT_GT(alone.size(), 200u);
  EXPECT_LT(alone.back(), alone.front() - 1);  // it drove
  EXPECT_EQ(samples(1), alone);
  EXPECT_EQ(samples(2), alone);
}

INSTANTIATE_TEST_SUITE_P(BothEngines, MotionEnergy, kEngines, EngineName);

}  // namespace
}  // namespace sanet
