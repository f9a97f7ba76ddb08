// Every scenario that ships with sanet loads and passes validation.
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

}  // namespace
}  // namespace sanet
