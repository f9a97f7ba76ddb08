// A run ends when its end condition has happened `count` times over all nodes: a logged line, a
// state entered, a metric reported.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scenario/scenario_loader.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;

struct Ended {
  std::string by;
  double at = 0;
  std::string dir;
};

Ended RunWith(const std::string& file, const std::vector<std::string>& sets, const std::string& tag) {
  const sim::RunSpec spec = scenario::LoadScenario(std::string(SANET_SOURCE_DIR) + "/scenarios/" + file, sets).run;
  const std::string dir = ::testing::TempDir() + "/sanet-end-" + tag;
  std::filesystem::remove_all(dir);
  sim::World world(spec, BuiltinRegistry());
  world.Run({dir, ""});
  return {world.ended_by(), world.ended_at(), dir};
}

// The times of the rows of a results CSV whose column `column` (0-based) is `value`.
std::vector<double> TimesOf(const std::string& path, int column, const std::string& value) {
  std::ifstream in(path);
  std::vector<double> times;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    if (static_cast<int>(cells.size()) > column && cells[column] == value) times.push_back(std::stod(cells[0]));
  }
  return times;
}

TEST(EndCondition, TheCountthStateEnteredEndsTheRun) {
  const Ended e =
      RunWith("help-request.yaml", {"end.when_transition=find_next_hop", "end.count=3", "end.grace=0"}, "transition");
  const auto entered = TimesOf(e.dir + "/transitions.csv", 3, "find_next_hop");
  ASSERT_GE(entered.size(), 3u);
  EXPECT_EQ(e.at, entered[2]);
  EXPECT_NE(e.by.find("entered 'find_next_hop' (3 in all)"), std::string::npos) << e.by;
}

TEST(EndCondition, TheCountthMetricReportEndsTheRun) {
  const Ended e = RunWith("help-request.yaml", {"end.when_metric=hop_time", "end.count=2", "end.grace=0"}, "metric");
  const auto reported = TimesOf(e.dir + "/metrics.csv", 2, "hop_time");
  ASSERT_EQ(reported.size(), 2u);
  EXPECT_EQ(e.at, reported[1]);
  EXPECT_NE(e.by.find("reported 'hop_time'"), std::string::npos) << e.by;
}

TEST(EndCondition, TheTeamEndsWhenItsThreeCallsAreAnswered) {
  const Ended e = RunWith("help-request-team.yaml", {}, "team");
  const auto arrived = TimesOf(e.dir + "/log.csv", 2, "arrived");
  ASSERT_EQ(arrived.size(), 3u);
  EXPECT_EQ(e.at, arrived[2]);
  EXPECT_LT(e.at, 1000);  // of the 1500 s it would simulate otherwise
}

}  // namespace
}  // namespace sanet
