// The same scenario and seed give byte-identical outputs; another seed with noise does not.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenario/scenario_loader.h"
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
  const sim::RunResult r = world.Run({dir, "", false});
  return {r.fingerprint, ReadFile(dir + "/trajectories.csv"), ReadFile(dir + "/log.csv")};
}

sim::RunSpec NoisyScenario(std::uint64_t seed) {
  sim::RunSpec spec = scenario::LoadScenario(SANET_SOURCE_DIR "/scenarios/around-the-wall.yaml").run;
  spec.duration = 40;
  spec.seed = seed;
  spec.nodes[0].model.sensors.ir->noise = 0.02;
  spec.nodes[0].model.sensors.ground_truth_noise_position = 0.01;
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

}  // namespace
}  // namespace sanet
