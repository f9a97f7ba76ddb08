// Every scenario that ships with sanet loads, passes validation and runs (shortened).
#include <gtest/gtest.h>

#include <filesystem>

#include "scenario/scenario_loader.h"
#include "support/test_world.h"

namespace sanet {
namespace {

TEST(ShippedScenarios, AllValidate) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SANET_SOURCE_DIR "/scenarios")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW({
      const scenario::Scenario sc = scenario::LoadScenario(entry.path().string());
      scenario::CheckControllers(sc, testing::BuiltinRegistry());
    });
    ++count;
  }
  EXPECT_GT(count, 0);
}

// The first simulated half second of each, without writing results: a scenario that validates
// but cannot start (a controller that throws in Start, a body the engine refuses) fails here.
TEST(ShippedScenarios, AllRunShortened) {
  for (const auto& entry : std::filesystem::directory_iterator(SANET_SOURCE_DIR "/scenarios")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    sim::RunSpec spec = scenario::LoadScenario(entry.path().string()).run;
    spec.duration = 0.5;
    sim::World world(spec, testing::BuiltinRegistry());
    const sim::RunResult r = world.Run({});
    EXPECT_GE(r.simulated, 0.5 - 1e-9);
    EXPECT_GT(r.events, 0u);
  }
}

}  // namespace
}  // namespace sanet
