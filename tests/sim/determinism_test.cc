// The same scenario and seed give byte-identical outputs; another seed with noise does not.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenario/scenario_loader.h"
#include "sensors/ground_truth/ground_truth.h"
#include "sensors/odometry/odometry.h"
#include "sensors/range_fan.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;

struct Outputs {
  std::string fingerprint, trajectories, log;
};

Outputs RunScenario(sim::RunSpec spec, const std::string& tag) {
  const std::string dir = ::testing::TempDir() + "/sanet-determinism-" + tag;
  std::filesystem::remove_all(dir);
  sim::World world(spec, BuiltinRegistry());
  const sim::RunResult r = world.Run({dir, ""});
  return {r.fingerprint, ReadFile(dir + "/trajectories.csv"), ReadFile(dir + "/log.csv")};
}

sim::RunSpec NoisyScenario(std::uint64_t seed) {
  sim::RunSpec spec = scenario::LoadScenario(SANET_SOURCE_DIR "/scenarios/around-the-wall.yaml").run;
  spec.duration = 40;
  spec.seed = seed;
  SensorSettings<sensors::RangeFan>(spec.nodes[0], "ir").noise = 0.02;
  SensorSettings<sensors::GroundTruthSettings>(spec.nodes[0], "ground_truth").noise_position = 0.01;
  return spec;
}

TEST(Determinism, SameScenarioAndSeedGiveIdenticalBytes) {
  const Outputs a = RunScenario(NoisyScenario(5), "a");
  const Outputs b = RunScenario(NoisyScenario(5), "b");
  ASSERT_GT(a.trajectories.size(), 1000u);
  EXPECT_EQ(a.trajectories, b.trajectories);
  EXPECT_EQ(a.log, b.log);
  EXPECT_EQ(a.fingerprint, b.fingerprint);
}

TEST(Determinism, AnotherSeedWithSensorNoiseGivesAnotherFingerprint) {
  const Outputs a = RunScenario(NoisyScenario(5), "c");
  const Outputs b = RunScenario(NoisyScenario(6), "d");
  EXPECT_NE(a.trajectories, b.trajectories);
  EXPECT_NE(a.fingerprint, b.fingerprint);
}

// A robot that steers by odometry (updated by the physics step) and noisy sensors: the same bytes
// with the physics on its own thread.
TEST(Determinism, OdometryReadsGiveTheSameBytesOnTwoThreads) {
  sim::RunSpec spec = NoisyScenario(7);
  ParamValue odometry;
  odometry.rows = {{"odometry"}};
  spec.nodes[0].controller->params.Set("localization", odometry);
  SensorSettings<sensors::OdometrySettings>(spec.nodes[0], "odometry").noise = 0.02;
  const Outputs one = RunScenario(spec, "odometry-1");
  spec.threads = 2;
  const Outputs two = RunScenario(spec, "odometry-2");
  ASSERT_GT(one.trajectories.size(), 1000u);
  EXPECT_EQ(one.trajectories, two.trajectories);
  EXPECT_EQ(one.fingerprint, two.fingerprint);
}

// With a physics thread (world.threads: 2) the run gives the bytes of a run with one: 3D with
// the radio, AODV and a robot steering by bearing and IR (help-request); 3D with lasers and
// broadcasts (formation); 2D with a thousand robots (swarm-1k).
struct ThreadedCase {
  const char* scenario;
  double duration;
};

class OneThreadOrTwo : public ::testing::TestWithParam<ThreadedCase> {};

TEST_P(OneThreadOrTwo, GiveIdenticalBytes) {
  sim::RunSpec spec = scenario::LoadScenario(std::string(SANET_SOURCE_DIR "/scenarios/") + GetParam().scenario).run;
  spec.duration = GetParam().duration;
  spec.figures = false;
  spec.threads = 1;
  const std::string tag = std::string("threads-") + GetParam().scenario;
  const Outputs one = RunScenario(spec, tag + "-1");
  spec.threads = 2;
  const Outputs two = RunScenario(spec, tag + "-2");
  ASSERT_GT(one.trajectories.size(), 1000u);
  EXPECT_EQ(one.trajectories, two.trajectories);
  EXPECT_EQ(one.log, two.log);
  EXPECT_EQ(one.fingerprint, two.fingerprint);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, OneThreadOrTwo,
                         ::testing::Values(ThreadedCase{"help-request.yaml", 120}, ThreadedCase{"formation.yaml", 40},
                                           ThreadedCase{"swarm-1k.yaml", 3}),
                         [](const auto& info) {
                           std::string name = info.param.scenario;
                           name = name.substr(0, name.find('.'));
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

}  // namespace
}  // namespace sanet

namespace sanet {
namespace {

// A run stepped from outside (World::Start, RunUntil, Finish) in uneven pieces gives the same
// results as one Run: the same fingerprint, events and end.
TEST(Stepping, PiecesGiveTheRunOfOneGo) {
  const auto run_file = [](const std::string& file, const std::vector<double>& stops) {
    sim::RunSpec spec = scenario::LoadScenario(std::string(SANET_SOURCE_DIR "/scenarios/") + file).run;
    spec.duration = std::min(spec.duration, 60.0);
    sim::World world(spec, testing::BuiltinRegistry());
    sim::RunOptions options;
    if (stops.empty()) {
      const sim::RunResult r = world.Run(options);
      return std::make_tuple(r.fingerprint, r.events, world.ended_by());
    }
    world.Start(options);
    for (double t : stops)
      if (!world.RunUntil(t)) break;
    EXPECT_FALSE(world.RunUntil(1e9)) << "the run is over at its end";
    const sim::RunResult r = world.Finish();
    return std::make_tuple(r.fingerprint, r.events, world.ended_by());
  };
  for (const char* file : {"around-the-wall.yaml", "help-request.yaml", "sensor-network.yaml"}) {
    const auto whole = run_file(file, {});
    EXPECT_EQ(run_file(file, {0, 0.0025, 1.7, 1.7, 13.333, 30}), whole) << file;
  }
}

}  // namespace
}  // namespace sanet
