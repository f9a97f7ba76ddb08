// --set: values from the command line change the scenario and are checked like the file;
// a mistake names the option.
#include <gtest/gtest.h>

#include <fstream>

#include "scenario/effective_scenario.h"
#include "scenario/scenario_loader.h"
#include "support/test_world.h"

namespace sanet {
namespace {

std::string Shipped(const char* name) { return std::string(SANET_SOURCE_DIR) + "/scenarios/" + name; }

const sim::NodeSpec& NodeNamed(const scenario::Scenario& sc, const std::string& name) {
  for (const auto& n : sc.run.nodes)
    if (n.name == name) return n;
  throw std::runtime_error("no node " + name);
}

double Param(const sim::NodeSpec& node, const std::string& key) { return node.controller->params.Number(key, -1); }

TEST(Overrides, ChangeNetworkAndANamedNodesController) {
  const auto sc = scenario::LoadScenario(Shipped("help-request.yaml"),
                                         {"network.tx_power=25", "nodes.robot.controller.params.speed=0.25", "seed=7"});
  EXPECT_EQ(sc.run.network->tx_power, 25);
  EXPECT_EQ(Param(NodeNamed(sc, "robot"), "speed"), 0.25);
  EXPECT_EQ(sc.run.seed, 7u);
}

TEST(Overrides, AGridNameReachesEveryNodeOfTheGrid) {
  const auto sc = scenario::LoadScenario(Shipped("swarm-1k.yaml"), {"nodes.r.controller.params.speed=0.45"});
  ASSERT_EQ(sc.run.nodes.size(), 1000u);
  for (const auto& n : sc.run.nodes) ASSERT_EQ(Param(n, "speed"), 0.45) << n.name;
}

TEST(Overrides, AnIndexReachesAnItemWithoutAName) {
  const auto sc = scenario::LoadScenario(Shipped("swarm-1k.yaml"), {"world.obstacles.2.wall.height=2.5"});
  EXPECT_EQ(sc.run.obstacles.at(2).box.size.z, 2.5);
}

TEST(Overrides, AnItemMayBeNamedAsErrorsPrintIt) {
  const auto sc = scenario::LoadScenario(
      Shipped("help-request.yaml"), {"nodes[robot].controller.params.speed=0.3", "world.obstacles[0].wall.height=2.5"});
  EXPECT_EQ(Param(NodeNamed(sc, "robot"), "speed"), 0.3);
  EXPECT_EQ(sc.run.obstacles.at(0).box.size.z, 2.5);
  const auto by_index = scenario::LoadScenario(Shipped("help-request.yaml"), {"nodes[3].controller.params.speed=0.4"});
  EXPECT_EQ(Param(NodeNamed(by_index, "robot"), "speed"), 0.4);  // the fourth item: the robot
  EXPECT_THROW(scenario::LoadScenario(Shipped("help-request.yaml"), {"nodes[robot]x.pose=[1, 2, 0]"}),
               scenario::ScenarioError);
}

TEST(Overrides, MissingMappingsAreCreated) {
  const auto sc = scenario::LoadScenario(Shipped("around-the-wall.yaml"), {"outputs.folder=/tmp/elsewhere"});
  EXPECT_EQ(sc.output_folder, "/tmp/elsewhere");
}

TEST(Overrides, TheEffectiveScenarioAndItsFingerprintFollowTheValue) {
  const auto plain = scenario::LoadScenario(Shipped("help-request.yaml"));
  const auto same = scenario::LoadScenario(Shipped("help-request.yaml"), {"network.tx_power=30"});  // the file's
  const auto other = scenario::LoadScenario(Shipped("help-request.yaml"), {"network.tx_power=20"});
  EXPECT_EQ(scenario::ScenarioFingerprint(plain), scenario::ScenarioFingerprint(same));
  EXPECT_NE(scenario::ScenarioFingerprint(plain), scenario::ScenarioFingerprint(other));
  EXPECT_NE(scenario::EffectiveScenarioYaml(other).find("--set network.tx_power=20"), std::string::npos);
}

struct Refused {
  const char* set;
  const char* field;
  const char* message;
};

void PrintTo(const Refused& c, std::ostream* os) { *os << c.set; }

class BadOverride : public ::testing::TestWithParam<Refused> {};

TEST_P(BadOverride, IsRefusedNamingTheOption) {
  const Refused& c = GetParam();
  try {
    const auto sc = scenario::LoadScenario(Shipped("swarm-1k.yaml"), {"seed=3", c.set});
    scenario::CheckControllers(sc, testing::BuiltinRegistry());
    FAIL() << c.set << " was accepted";
  } catch (const scenario::ScenarioError& e) {
    EXPECT_EQ(e.file(), std::string("--set ") + c.set);
    EXPECT_EQ(e.field(), c.field) << e.what();
    EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenario, BadOverride,
    ::testing::Values(Refused{"network.tx_power=loud", "network.tx_power", "must be a number"},
                      Refused{"network.txpower=3", "network.txpower", "unknown key"},
                      Refused{"nodes.r.controller.params.speed=-1", "nodes[0].controller.params.speed", "is -1"},
                      Refused{"nodes.q.model=mote", "nodes", "no item named 'q': did you mean r? (items: r)"},
                      Refused{"seed.low=1", "seed", "is a value, not a mapping"},
                      Refused{"network..port=1", "network", "empty key"},
                      Refused{"world.size=[1, 2", "world.size", "not valid YAML"},
                      Refused{"noequals", "", "expected PATH=VALUE"}),
    [](const auto& info) { return "case" + std::to_string(info.index); });

TEST(Overrides, AMisspeltItemSuggestsTheNameMeantEvenPastTheListShown) {
  try {
    scenario::LoadScenario(Shipped("charging-robot.yaml"), {"nodes.chargr.controller.params.visits=false"});
    FAIL() << "accepted";
  } catch (const scenario::ScenarioError& e) {
    EXPECT_NE(e.message().find("did you mean charger?"), std::string::npos) << e.what();
  }
}

TEST(Overrides, AnErrorElsewhereKeepsTheFilesLine) {
  const std::string path = ::testing::TempDir() + "/overrides-elsewhere.yaml";
  std::ofstream(path)
      << "duration: 10\nnodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\noutputs:\n  trajectory_interval: 0.05\n";
  try {
    scenario::LoadScenario(path, {"world.physics_step=0.1"});
    FAIL();
  } catch (const scenario::ScenarioError& e) {
    EXPECT_EQ(e.file(), path);  // the interval, now below the step, is the file's
    EXPECT_EQ(e.line(), 5);
    EXPECT_EQ(e.field(), "outputs.trajectory_interval");
  }
}

}  // namespace
}  // namespace sanet
