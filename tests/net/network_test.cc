// The wireless network: multi-hop delivery, links that follow physical distance, routing views
// that agree with ns-3, broadcasts, pcap files, reproducibility.
#include <gtest/gtest.h>
#include <ns3/aodv-routing-protocol.h>
#include <ns3/ipv4.h>
#include <ns3/node-list.h>
#include <ns3/node.h>
#include <ns3/output-stream-wrapper.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

// Range of the default radio (16 dBm, log-distance exponent 3, 46.6777 dB at 1 m, frames
// detected above -82 dBm): 16 - 46.6777 - 30 log10(d) = -82.
const double kPredictedRange = std::pow(10.0, (16 - 46.6777 + 82) / 30);

// Records what reaches it and runs a script of sends: (time, to or kBroadcast, flood).
class Probe : public Controller {
 public:
  struct Send {
    double time;
    NodeId to;
    bool flood = false;
  };
  Probe(std::vector<Message>* inbox, std::vector<Send> script, std::function<void(Node&)> step = nullptr)
      : inbox_(inbox), script_(std::move(script)), step_(std::move(step)) {}
  void ControlStep(Node& node) override {
    while (next_ < script_.size() && script_[next_].time <= node.Now() + 1e-9) {
      const Send& s = script_[next_++];
      const Bytes payload{1, 2, 3, 4};
      if (s.flood)
        node.Flood(payload);
      else if (s.to == kBroadcast)
        node.Broadcast(payload);
      else
        node.Send(s.to, payload);
    }
    if (step_) step_(node);
  }
  void OnMessage(Node& node, const Message& m) override {
    inbox_->push_back(m);
    if (auto pose = node.GroundTruth()) where_.push_back(pose->position());
  }
  static inline std::vector<Vec2> where_;  // where the receiver was at each reception

 private:
  std::vector<Message>* inbox_;
  std::vector<Send> script_;
  std::function<void(Node&)> step_;
  std::size_t next_ = 0;
};

// Registers probe controllers "p0", "p1", ... with their inboxes and scripts.
struct Probes {
  hosting::Registry registry;
  std::vector<std::vector<Message>> inboxes;
  explicit Probes(std::vector<std::vector<Probe::Send>> scripts, std::vector<std::function<void(Node&)>> steps = {})
      : inboxes(scripts.size()) {
    steps.resize(scripts.size());
    for (std::size_t i = 0; i < scripts.size(); ++i)
      registry.Add({"p" + std::to_string(i), "", [this, i, s = scripts[i], f = steps[i]](const Params&) {
                      return std::make_unique<Probe>(&inboxes[i], s, f);
                    }});
  }
};

sim::RunSpec MoteLine(int motes, double spacing, net::Routing routing, double duration) {
  sim::RunSpec spec;
  spec.duration = duration;
  spec.network = net::NetworkSpec{};
  spec.network->routing = routing;
  for (int i = 0; i < motes; ++i)
    spec.nodes.push_back(Robot("m" + std::to_string(i), ModelKind::kMote, {spacing * i, 0, 0}));
  return spec;
}

TEST(Network, AodvCarriesAMessageFiveHopsAlongALine) {
  Probes probes({{{2, 5}, {4, 5}, {6, 5}}, {}});
  sim::RunSpec spec = MoteLine(6, 40, net::Routing::kAodv, 10);
  spec.nodes[0].controller = UseController("p0", {});
  spec.nodes[5].controller = UseController("p1", {});
  sim::World world(spec, probes.registry);
  world.Run({});
  const auto& got = probes.inboxes[1];
  ASSERT_EQ(got.size(), 3u) << "every message should arrive";
  for (const Message& m : got) {
    EXPECT_EQ(m.from, 0u);
    EXPECT_EQ(m.delivery, Delivery::kUnicast);
    ASSERT_TRUE(m.hops);
    EXPECT_EQ(*m.hops, 5);
    EXPECT_GT(m.time_received, m.time_sent);
  }
}

class ProactiveRouting : public ::testing::TestWithParam<net::Routing> {};

TEST_P(ProactiveRouting, BuildsTablesAndCarriesMessagesFourHops) {
  std::vector<RouteEntry> table;
  auto read = [&](Node& node) {
    if (node.Now() >= 14 && table.empty()) table = node.Network().RoutingTable();
  };
  Probes probes({{{15, 4}, {16, 4}, {17, 4}}, {}}, {read, nullptr});
  sim::RunSpec spec = MoteLine(5, 40, GetParam(), 20);
  spec.nodes[0].controller = UseController("p0", {});
  spec.nodes[4].controller = UseController("p1", {});
  sim::World world(spec, probes.registry);
  world.Run({});
  bool found = false;
  for (const RouteEntry& e : table)
    if (e.destination == 4) found = e.valid && e.hops == 4 && e.next_hop == 1;
  EXPECT_TRUE(found) << "m0 knows m4, four hops away through m1";
  EXPECT_GE(probes.inboxes[1].size(), 2u);
  for (const Message& m : probes.inboxes[1]) EXPECT_EQ(*m.hops, 4);
}

INSTANTIATE_TEST_SUITE_P(Network, ProactiveRouting, ::testing::Values(net::Routing::kOlsr, net::Routing::kDsdv),
                         [](const auto& info) { return std::string(net::RoutingName(info.param)); });

TEST(Network, RandomPropagationDelayStillCarriesAcknowledgedUnicast) {
  Probes probes({{{2, 3}, {3, 3}, {4, 3}}, {}});
  sim::RunSpec spec = MoteLine(4, 40, net::Routing::kAodv, 8);
  spec.network->delay = net::DelayModel::kRandom;
  spec.network->random_delay_max = 20e-6;
  spec.nodes[0].controller = UseController("p0", {});
  spec.nodes[3].controller = UseController("p1", {});
  sim::World world(spec, probes.registry);
  world.Run({});
  EXPECT_EQ(probes.inboxes[1].size(), 3u);
}

TEST(Network, WithoutRoutingAMessageDoesNotGoBeyondOneHop) {
  Probes probes({{{2, 5}, {4, 5}, {6, 1}}, {}, {}});
  sim::RunSpec spec = MoteLine(6, 40, net::Routing::kNone, 10);
  spec.nodes[0].controller = UseController("p0", {});
  spec.nodes[5].controller = UseController("p1", {});
  spec.nodes[1].controller = UseController("p2", {});
  sim::World world(spec, probes.registry);
  world.Run({});
  EXPECT_TRUE(probes.inboxes[1].empty()) << "five hops away, no routing";
  ASSERT_EQ(probes.inboxes[2].size(), 1u) << "the neighbour still hears it";
  EXPECT_EQ(*probes.inboxes[2][0].hops, 1);
}

TEST(Network, BroadcastReachesExactlyTheNodesInRange) {
  Probes probes({{{1, kBroadcast}}, {}, {}, {}, {}, {}});
  sim::RunSpec spec = MoteLine(0, 0, net::Routing::kAodv, 3);
  const double distances[] = {0, 10, 30, 0.9 * kPredictedRange, 1.1 * kPredictedRange, 80};
  for (int i = 0; i < 6; ++i)
    spec.nodes.push_back(Robot("n" + std::to_string(i), ModelKind::kMote, {distances[i], 0, 0},
                               UseController("p" + std::to_string(i), {})));
  sim::World world(spec, probes.registry);
  world.Run({});
  for (int i = 1; i < 6; ++i) {
    const bool in_range = distances[i] < kPredictedRange;
    EXPECT_EQ(probes.inboxes[i].size(), in_range ? 1u : 0u) << "node at " << distances[i] << " m";
  }
}

TEST(Network, FloodingReachesTheWholeLineOnce) {
  Probes probes({{{2, kBroadcast, true}}, {}, {}, {}, {}, {}});
  sim::RunSpec spec = MoteLine(6, 40, net::Routing::kNone, 5);
  for (int i = 0; i < 6; ++i) spec.nodes[i].controller = UseController("p" + std::to_string(i), {});
  sim::World world(spec, probes.registry);
  world.Run({});
  for (int i = 1; i < 6; ++i) {
    ASSERT_EQ(probes.inboxes[i].size(), 1u) << "node " << i;
    EXPECT_EQ(*probes.inboxes[i][0].hops, i);
    EXPECT_EQ(probes.inboxes[i][0].delivery, Delivery::kFlood);
  }
}

TEST(Network, ARobotDrivingAwayLosesTheLinkWhereThePropagationModelSaysAndRegainsIt) {
  // The mote broadcasts every 0.2 s; the robot drives out to 80 m at 1 m/s and comes back.
  std::vector<Probe::Send> beacons;
  for (double t = 0.2; t < 200; t += 0.2) beacons.push_back({t, kBroadcast});
  auto drive = [outbound = true](Node& node) mutable {
    const double x = node.GroundTruth()->x;
    if (x > 80) outbound = false;
    node.Drive({outbound ? 1.0 : x > 5 ? -1.0 : 0.0, 0, 0});
  };
  Probes probes({beacons, {}}, {nullptr, drive});
  Probe::where_.clear();
  sim::RunSpec spec = MoteLine(0, 0, net::Routing::kNone, 170);
  spec.nodes.push_back(Robot("mote", ModelKind::kMote, {0, 0, 0}, UseController("p0", {})));
  spec.nodes.push_back(Robot("robot", ModelKind::kOmni3, {2, 0, 0}, UseController("p1", {})));
  sim::World world(spec, probes.registry);
  world.Run({});
  const auto& got = probes.inboxes[1];
  ASSERT_EQ(got.size(), Probe::where_.size());
  // Outbound: the last reception before the silence; back: the first one after it.
  std::size_t gap = 0;
  for (std::size_t i = 1; i < got.size(); ++i)
    if (got[i].time_received - got[i - 1].time_received > 5) gap = i;
  ASSERT_GT(gap, 0u) << "the link never broke";
  const double lost_at = Norm(Probe::where_[gap - 1]);
  const double regained_at = Norm(Probe::where_[gap]);
  EXPECT_NEAR(lost_at, kPredictedRange, 0.1 * kPredictedRange);
  EXPECT_NEAR(regained_at, kPredictedRange, 0.1 * kPredictedRange);
  for (const Vec2& p : Probe::where_) EXPECT_LT(Norm(p), 1.1 * kPredictedRange) << "heard beyond the range";
  EXPECT_LT(Norm(Probe::where_.back()), 10) << "heard again on the way home";
}

// A mote at the origin broadcasts every 0.2 s at 0 dBm (heard to 15 m); a robot drives along
// x = 10 m from y = -11 to 11 m. A concrete wall 0.3 m thick (15.6 dB at 2.4 GHz) from (5, -4)
// to (5, 4) shades |y| < 8.25 m there (its near corners seen from the mote): behind it the
// mote's -80 to -78 dBm fall under the -82 dBm threshold, and no frame gets through.
std::vector<Vec2> HeardAlongTheWall(net::Material material) {
  std::vector<Probe::Send> beacons;
  for (double t = 0.2; t < 30; t += 0.2) beacons.push_back({t, kBroadcast});
  auto drive = [](Node& node) { node.Drive({node.GroundTruth()->y < 11 ? 1.0 : 0.0, 0, 0}); };
  Probes probes({beacons, {}}, {nullptr, drive});
  Probe::where_.clear();
  sim::RunSpec spec = MoteLine(0, 0, net::Routing::kNone, 24);
  spec.network->tx_power = 0;
  spec.nodes.push_back(Robot("mote", ModelKind::kMote, {0, 0, 0}, UseController("p0", {})));
  spec.nodes.push_back(Robot("robot", ModelKind::kOmni3, {10, -11, M_PI / 2}, UseController("p1", {})));
  spec.obstacles.push_back(Wall({5, -4}, {5, 4}, 2.0, 0.3));
  spec.obstacles.back().material = material;
  sim::World world(spec, probes.registry);
  world.Run({});
  return Probe::where_;
}

TEST(Network, ARobotBehindAConcreteWallLosesTheMoteAndHearsItAgainPastIt) {
  const std::vector<Vec2> heard = HeardAlongTheWall(net::Material::kConcrete);
  ASSERT_GT(heard.size(), 20u);
  std::size_t gap = 0;
  for (std::size_t i = 1; i < heard.size(); ++i)
    if (heard[i].y - heard[i - 1].y > 5) gap = i;
  ASSERT_GT(gap, 0u) << "the wall never cut the link";
  EXPECT_NEAR(heard[gap - 1].y, -8.25, 0.5) << "lost where the wall's shadow begins";
  EXPECT_NEAR(heard[gap].y, 8.25, 0.5) << "heard again where it ends";
  for (const Vec2& p : heard) EXPECT_GT(std::fabs(p.y), 7.7) << "heard through the wall";
  EXPECT_GT(heard.back().y, 10) << "heard past the wall to the end";
  // The same wall of no material: the robot hears the mote all the way.
  const std::vector<Vec2> open = HeardAlongTheWall(net::Material::kNone);
  for (std::size_t i = 1; i < open.size(); ++i) EXPECT_LT(open[i].y - open[i - 1].y, 1.0) << "a gap without loss";
}

TEST(Network, RoutingTableAgreesWithNs3AndInvalidationStartsANewDiscovery) {
  // m0 sends to m4 at 2 s; at 2.5 s, while the route is active, it compares its table with
  // ns-3's own dump, invalidates the route to m4 and sends again, which needs a new discovery.
  std::vector<RouteEntry> table_before, table_after;
  std::string ns3_dump;
  bool invalidated = false;
  auto check = [&](Node& node) {
    if (node.Now() >= 2.5 && !invalidated) {
      table_before = node.Network().RoutingTable();
      auto aodv = ns3::DynamicCast<ns3::aodv::RoutingProtocol>(
          ns3::NodeList::GetNode(node.Id())->GetObject<ns3::Ipv4>()->GetRoutingProtocol());
      std::ostringstream text;
      aodv->PrintRoutingTable(ns3::Create<ns3::OutputStreamWrapper>(&text));
      ns3_dump = text.str();
      EXPECT_TRUE(node.Network().InvalidateRoute(4));
      table_after = node.Network().RoutingTable();
      node.Send(4, {9});
      invalidated = true;
    }
  };
  Probes probes({{{2, 4}, {4, 4}, {6, 4}, {8, 4}}, {}}, {check, nullptr});
  sim::RunSpec spec = MoteLine(5, 40, net::Routing::kAodv, 10);
  spec.nodes[0].controller = UseController("p0", {});
  spec.nodes[4].controller = UseController("p1", {});
  const std::string dir = ::testing::TempDir() + "/sanet-invalidate";
  std::filesystem::remove_all(dir);
  sim::World world(spec, probes.registry);
  world.Run({dir, ""});

  // ns-3's dump: "Destination Gateway Interface Flag Expire Hops" per line.
  std::map<std::string, std::vector<std::string>> dumped;
  std::istringstream lines(ns3_dump);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::vector<std::string> w{std::istream_iterator<std::string>(words), {}};
    if (w.size() == 6 && w[0].rfind("10.0.0.", 0) == 0) dumped[w[0]] = w;
  }
  int compared = 0;
  for (const RouteEntry& e : table_before) {
    if (!e.valid) continue;
    const std::string destination = "10.0.0." + std::to_string(e.destination + 1);
    ASSERT_TRUE(dumped.count(destination)) << destination << " not in\n" << ns3_dump;
    const auto& w = dumped[destination];
    EXPECT_EQ(w[1], "10.0.0." + std::to_string(e.next_hop + 1)) << "next hop of " << destination;
    EXPECT_EQ(w[3], "UP");
    EXPECT_EQ(w[5], std::to_string(e.hops)) << "hops to " << destination;
    ++compared;
  }
  EXPECT_GE(compared, 2);
  bool route_to_4 = false;
  for (const RouteEntry& e : table_before)
    if (e.destination == 4) route_to_4 = e.valid && e.hops == 4 && e.next_hop == 1;
  EXPECT_TRUE(route_to_4) << "m0 reaches m4 in four hops through m1";
  for (const RouteEntry& e : table_after)
    if (e.destination == 4) {
      EXPECT_FALSE(e.valid) << "invalidated";
    }

  EXPECT_GE(probes.inboxes[1].size(), 3u) << "messages arrive before and after the invalidation";
  const std::string routes = ReadFile(dir + "/routes.csv");
  std::size_t discoveries = 0;
  for (std::size_t at = 0; (at = routes.find("\nm0,m4,", at)) != std::string::npos; ++at) ++discoveries;
  EXPECT_EQ(discoveries, 2u) << routes;
  EXPECT_NE(routes.find("\nm0,m4,2.5"), std::string::npos) << "the second starts at the resend\n" << routes;
}

// Counts the 802.11 data frames in a pcap file that carry UDP to `port` from `source`.
int CountUdpFrames(const std::string& path, std::uint16_t port, const std::string& source) {
  const std::string data = ReadFile(path);
  if (data.size() < 24) return -1;
  std::uint32_t magic;
  std::memcpy(&magic, data.data(), 4);
  if (magic != 0xa1b2c3d4) return -1;
  std::uint32_t link;
  std::memcpy(&link, data.data() + 20, 4);
  if (link != 105) return -1;  // IEEE 802.11
  int count = 0;
  for (std::size_t at = 24; at + 16 <= data.size();) {
    std::uint32_t captured;
    std::memcpy(&captured, data.data() + at + 8, 4);
    const auto* f = reinterpret_cast<const unsigned char*>(data.data() + at + 16);
    at += 16 + captured;
    if (captured < 24 + 8 + 20 + 8 || (f[0] & 0x0C) != 0x08) continue;  // data frames only
    const unsigned char* llc = f + 24;
    if (llc[6] != 0x08 || llc[7] != 0x00) continue;  // IPv4
    const unsigned char* ip = llc + 8;
    if (ip[9] != 17) continue;  // UDP
    char src[20];
    std::snprintf(src, sizeof src, "%d.%d.%d.%d", ip[12], ip[13], ip[14], ip[15]);
    const unsigned char* udp = ip + (ip[0] & 0x0F) * 4;
    if (src == source && (udp[2] << 8 | udp[3]) == port) ++count;
  }
  return count;
}

TEST(Network, PcapFilesHoldTheUdpPacketsSent) {
  Probes probes({{{1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, kBroadcast}}, {}});
  sim::RunSpec spec = MoteLine(2, 20, net::Routing::kAodv, 6);
  spec.network->pcap = true;
  spec.nodes[0].controller = UseController("p0", {});
  spec.nodes[1].controller = UseController("p1", {});
  const std::string dir = ::testing::TempDir() + "/sanet-pcap";
  std::filesystem::remove_all(dir);
  {
    sim::World world(spec, probes.registry);
    world.Run({dir, ""});
  }
  ASSERT_EQ(probes.inboxes[1].size(), 5u);
  EXPECT_EQ(CountUdpFrames(dir + "/pcap/m0.pcap", 9000, "10.0.0.1"), 5) << "sent by m0";
  EXPECT_EQ(CountUdpFrames(dir + "/pcap/m1.pcap", 9000, "10.0.0.1"), 5) << "received by m1";
  EXPECT_FALSE(std::filesystem::exists(dir + "/pcap.tmp"));
}

TEST(Network, SameSeedGivesIdenticalDelayAndPacketFiles) {
  auto run = [](const std::string& tag) {
    sim::RunSpec spec = MoteLine(8, 35, net::Routing::kAodv, 20);
    spec.seed = 11;
    for (int i = 0; i < 8; i += 3)
      spec.nodes[i].controller = UseController("pinger", {{"to", Scalar(0)}, {"interval", Scalar(0.7)}});
    spec.nodes[0].controller = UseController("pinger", {{"interval", Scalar(0.5)}});
    spec.nodes[0].controller->params.Set("to", ParamValue{ParamValue::Shape::kScalar, {{"m7"}}, 0});
    spec.nodes[3].controller->params.Set("to", ParamValue{ParamValue::Shape::kScalar, {{"flood"}}, 0});
    spec.nodes[6].controller->params.Set("to", ParamValue{ParamValue::Shape::kScalar, {{"broadcast"}}, 0});
    const std::string dir = ::testing::TempDir() + "/sanet-netdet-" + tag;
    std::filesystem::remove_all(dir);
    sim::World world(spec, BuiltinRegistry());
    world.Run({dir, ""});
    return dir;
  };
  const std::string a = run("a"), b = run("b");
  for (const char* f : {"messages.csv", "packets.csv", "routes.csv", "packets/m3.csv"}) {
    const std::string x = ReadFile(a + "/" + f);
    EXPECT_GT(x.size(), 60u) << f;
    EXPECT_EQ(x, ReadFile(b + "/" + f)) << f;
  }
}

}  // namespace
}  // namespace sanet
