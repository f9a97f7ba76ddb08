// network.ns3: ns-3's own attributes from a scenario, checked against ns-3's lists and in effect
// for the run (and only for it).
#include "net/ns3_attributes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scenario/scenario_loader.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;

bool Says(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Ns3Attributes, KnownAttributeAndValueAreTaken) {
  EXPECT_EQ(net::CheckNs3Attribute("ns3::aodv::RoutingProtocol::ActiveRouteTimeout", "10s"), "");
  EXPECT_EQ(net::CheckNs3Attribute("ns3::aodv::RoutingProtocol::RreqRetries", "4"), "");
  EXPECT_EQ(net::CheckNs3Attribute("ns3::WifiMacQueue::MaxSize", "50p"), "");
}

TEST(Ns3Attributes, MistakesAreExplained) {
  EXPECT_TRUE(Says(net::CheckNs3Attribute("ns3::aodv::RoutingProtocol::ActiveRoutTimeout", "1s"),
                   "did you mean ActiveRouteTimeout"));
  EXPECT_TRUE(Says(net::CheckNs3Attribute("ns3::aodv::RoutingProtocl::ActiveRouteTimeout", "1s"),
                   "did you mean ns3::aodv::RoutingProtocol"));
  EXPECT_TRUE(Says(net::CheckNs3Attribute("ns3::YansWifiPhy::TxGain", "1"), "name it ns3::WifiPhy::TxGain"));
  EXPECT_TRUE(Says(net::CheckNs3Attribute("ns3::WifiPhy::TxPowerStart", "1"), "use network.tx_power"));
  EXPECT_TRUE(Says(net::CheckNs3Attribute("ActiveRouteTimeout", "1s"), "TYPE::ATTRIBUTE"));
  EXPECT_TRUE(Says(net::CheckNs3Attribute("ns3::aodv::RoutingProtocol::RreqRetries", "many"), "not a valid value"));
}

// ns-3 aborts the process when a pointer attribute names a type it does not know.
TEST(Ns3Attributes, AValueThatMakesNs3AbortIsRefusedWithoutAbortingUs) {
  const std::string why = net::CheckNs3Attribute("ns3::aodv::RoutingProtocol::UniformRv", "ns3::NoSuchVariable");
  EXPECT_TRUE(Says(why, "not a valid value")) << why;
}

TEST(Ns3Attributes, ATimeNeedsAUnitAndCannotBeNegative) {
  const std::string name = "ns3::aodv::RoutingProtocol::NodeTraversalTime";
  for (const char* bad : {"ten", "-5ms", "20", "5 parsecs"})
    EXPECT_TRUE(Says(net::CheckNs3Attribute(name, bad), "give a number of 0 or more with its unit")) << bad;
  for (const char* good : {"20ms", "1.5s", "2min", "+3us", "1e-2s"}) EXPECT_EQ(net::CheckNs3Attribute(name, good), "");
}

TEST(Ns3Attributes, AMisspeltAttributeInAFileIsRefusedOnItsLine) {
  const std::string path = ::testing::TempDir() + "/ns3-misspelt.yaml";
  std::ofstream(path) << "duration: 10\nnetwork:\n  ns3:\n    ns3::aodv::RoutingProtocol::HelloIntervall: 2s\n"
                         "nodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\n";
  try {
    scenario::LoadScenario(path);
    FAIL() << "accepted";
  } catch (const scenario::ScenarioError& e) {
    EXPECT_EQ(e.line(), 4);
    EXPECT_EQ(e.field(), "network.ns3.ns3::aodv::RoutingProtocol::HelloIntervall");
    EXPECT_TRUE(Says(e.message(), "did you mean HelloInterval")) << e.what();
  }
}

// The reporter of sensor-network asks for a route to the far corner every 5 s. AODV forgets an
// unused route after ActiveRouteTimeout (3 s in ns-3): each report discovers it anew. With 10 s
// the route outlives the gap between reports.
std::vector<double> DiscoveryStarts(const std::vector<std::string>& sets, const std::string& tag,
                                    std::string* fingerprint) {
  sim::RunSpec spec = scenario::LoadScenario(SANET_SOURCE_DIR "/scenarios/sensor-network.yaml", sets).run;
  spec.duration = 30;
  const std::string dir = ::testing::TempDir() + "/sanet-ns3-" + tag;
  std::filesystem::remove_all(dir);
  sim::World world(spec, BuiltinRegistry());
  *fingerprint = world.Run({dir, ""}).fingerprint;
  std::ifstream routes(dir + "/routes.csv");
  std::vector<double> starts;
  std::string line;
  std::getline(routes, line);  // header
  while (std::getline(routes, line))
    if (line.rfind("reporter,m24,", 0) == 0) starts.push_back(std::stod(line.substr(13)));
  return starts;
}

TEST(Ns3Attributes, ActiveRouteTimeoutDecidesWhenARouteExpiresAndOnlyForItsRun) {
  std::string before, with, after;
  const auto standard = DiscoveryStarts({}, "standard", &before);
  const auto longer =
      DiscoveryStarts({"network.ns3.ns3::aodv::RoutingProtocol::ActiveRouteTimeout=10s"}, "longer", &with);
  const auto again = DiscoveryStarts({}, "again", &after);
  ASSERT_GE(standard.size(), 4u);  // a discovery for nearly every report
  EXPECT_LE(longer.size(), 2u);    // the route stays while it is used every 5 s
  EXPECT_EQ(longer.front(), standard.front());
  EXPECT_NE(before, with);
  EXPECT_EQ(before, after);  // ns-3's own default is back for the next run
  EXPECT_EQ(standard, again);
}

}  // namespace
}  // namespace sanet
