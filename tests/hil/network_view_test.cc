// The routing view in the loop, the server's side: GETNET answers what the robot's ns-3 node
// holds at the poll that answers (compared here with the node itself, the world paused at
// once), rate-limited per client; INVALIDATEROUTE changes the node's table; a robot with no tap
// is told to read its own kernel. And the kernel view's map from addresses to nodes.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <map>
#include <set>
#include <sstream>

#include "robot_server/sim_server.h"
#include "sim/world.h"
#include "support/test_world.h"
#include "usarsim_agent/kernel_tables.h"
#include "wire/protocol.h"

namespace sanet {
namespace {

using robots::ModelKind;
using wire::ProtocolMessage;

// Motes 40 m apart (the default radio reaches 51 m: each hears its neighbours only) and a robot
// 40 m before the first.
sim::RunSpec MoteLineWithRobot() {
  sim::RunSpec spec;
  spec.duration = 30;
  spec.network = net::NetworkSpec{};
  for (int i = 0; i < 4; ++i)
    spec.nodes.push_back(testing::Robot("m" + std::to_string(i), ModelKind::kMote, {40.0 * i, 0, 0}));
  spec.nodes.push_back(testing::Robot("r", ModelKind::kOmni3, {-40, 0, 0},
                                      testing::UseController("constant_velocity", {{"vx", testing::Scalar(0)}})));
  return spec;
}

// A client of the robot server that writes lines and collects what comes back, without blocking.
class LineClient {
 public:
  explicit LineClient(std::uint16_t port) : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(port);
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    EXPECT_EQ(::connect(fd_, reinterpret_cast<sockaddr*>(&to), sizeof to), 0);
  }
  ~LineClient() { ::close(fd_); }
  void Say(const std::string& line) { ASSERT_GT(::send(fd_, (line + "\r\n").data(), line.size() + 2, 0), 0); }
  // Every whole line that has come, parsed.
  std::vector<wire::ProtocolMessage> Take() {
    char buffer[65536];
    pollfd p{fd_, POLLIN, 0};
    while (::poll(&p, 1, 0) > 0) {
      const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
      if (n <= 0) break;
      pending_.append(buffer, static_cast<std::size_t>(n));
    }
    std::vector<wire::ProtocolMessage> lines;
    for (std::size_t end; (end = pending_.find("\r\n")) != std::string::npos; pending_.erase(0, end + 2))
      if (auto m = wire::ParseLine(pending_.substr(0, end), nullptr)) lines.push_back(*m);
    return lines;
  }

 private:
  int fd_;
  std::string pending_;
};

struct Served {
  sim::World world;
  robot_server::SimServer server;
  LineClient client;
  double now = 0;
  Served(const sim::RunSpec& spec, bool tap)
      : world(spec, testing::BuiltinRegistry(), sim::RobotDrivers::kFrontEnds),
        server(world.driver(), Settings()),
        client(server.port()) {
    if (tap) JoinSocketPair();
    server.Start();
    world.Start({});
    client.Say("INIT {Name r}");
  }
  static robot_server::ServerSettings Settings() {
    robot_server::ServerSettings s;
    s.port = 0;
    return s;
  }
  // A socket pair stands in for the tap: the robot's node has a real stack joined to it.
  void JoinSocketPair() {
    int pair[2];
    ASSERT_EQ(::socketpair(AF_UNIX, SOCK_DGRAM, 0, pair), 0);
    world.driver().JoinTap(*world.Lookup("r"), pair[0], "02:00:00:00:00:05");
  }
  // Runs a poll period at a time until a line of `type` comes; the world stays where it was then.
  std::optional<wire::ProtocolMessage> RunUntilLine(const std::string& type, double limit) {
    for (; now < limit; now += 0.005) {
      world.RunUntil(now);
      for (const wire::ProtocolMessage& m : client.Take())
        if (m.type == type) return m;
    }
    return std::nullopt;
  }
  void RunTo(double t) {
    for (; now < t; now += 0.005) {
      world.RunUntil(now);
      client.Take();
    }
  }
};

std::string Row(const std::string& destination, const std::string& next, int hops, bool valid) {
  return destination + " Next " + next + " Hops " + std::to_string(hops) + " Valid " + (valid ? "True" : "False");
}

TEST(NetworkView, GetnetAnswersTheRobotsNs3NodeAtThatStep) {
  Served s(MoteLineWithRobot(), true);
  s.RunTo(1);
  s.client.Say("SEND {To m3} {Data 01}");  // a route discovery three motes away
  s.RunTo(4);
  s.client.Say("GETNET");
  const auto net = s.RunUntilLine("NET", 5);
  ASSERT_TRUE(net);
  const NodeId r = *s.world.Lookup("r");
  const NetworkView& truth = s.world.driver().NetworkOf(r);
  EXPECT_EQ(*net->Get("Source"), "Simulated");
  EXPECT_EQ(*net->Get("Protocol"), truth.Protocol());
  EXPECT_NEAR(*net->Number("Time"), s.world.driver().Now(), 0.0051);
  std::map<std::string, double> answered;  // row without expiry -> expiry
  for (const auto& [key, value] : net->fields)
    if (key == "Route") answered[value.substr(0, value.find(" Expires"))] = std::stod(value.substr(value.rfind(' ')));
  std::map<std::string, double> held;
  for (const RouteEntry& e : truth.RoutingTable())
    held[Row(s.world.NameOf(e.destination), s.world.NameOf(e.next_hop), e.hops, e.valid)] = e.expires_in;
  ASSERT_EQ(answered.size(), held.size());
  for (const auto& [row, expires] : held) {
    ASSERT_TRUE(answered.count(row)) << row;
    EXPECT_NEAR(answered[row], expires, 0.0051) << "one poll period apart at most";
  }
  EXPECT_TRUE(answered.count(Row("m3", "m0", 4, true))) << "the discovered route, through m0";
  std::set<std::string> neighbours, truly;
  for (const auto& [key, value] : net->fields)
    if (key == "Neighbour") neighbours.insert(value);
  for (NodeId n : truth.Neighbours()) truly.insert(s.world.NameOf(n));
  EXPECT_EQ(neighbours, truly);
  EXPECT_EQ(neighbours, std::set<std::string>{"m0"});
  s.world.Finish();
}

TEST(NetworkView, AsksWithinTheRateLimitWaitAndAreAnsweredTogether) {
  Served s(MoteLineWithRobot(), true);
  s.RunTo(1);
  s.client.Say("GETNET");
  const auto first = s.RunUntilLine("NET", 2);
  ASSERT_TRUE(first);
  for (int i = 0; i < 10; ++i) s.client.Say("GETNET");
  std::vector<double> times;
  for (double t = s.now; t < s.now + 0.1; t += 0.005) {
    s.world.RunUntil(t);
    for (const wire::ProtocolMessage& m : s.client.Take())
      if (m.type == "NET") times.push_back(*m.Number("Time"));
  }
  // The server takes a client's lines in bounded turns, so the asks may span polls; answers
  // never come closer together than the rate limit, and asks waiting together get one answer.
  ASSERT_FALSE(times.empty());
  EXPECT_LT(times.size(), 4u) << "ten asks, answered together";
  double last = *first->Number("Time");
  for (double t : times) {
    EXPECT_GE(t, last + robot_server::ServerSettings{}.net_period - 1e-6);
    last = t;
  }
  s.world.Finish();
}

TEST(NetworkView, InvalidateRouteDropsTheNodesRouteAndRequestRouteFindsOne) {
  Served s(MoteLineWithRobot(), true);
  s.RunTo(1);
  s.client.Say("REQUESTROUTE {To m2}");
  s.RunTo(3);
  const NodeId r = *s.world.Lookup("r"), m2 = *s.world.Lookup("m2");
  const auto valid_route = [&] {
    for (const RouteEntry& e : s.world.driver().NetworkOf(r).RoutingTable())
      if (e.destination == m2) return e.valid;
    return false;
  };
  ASSERT_TRUE(valid_route()) << "REQUESTROUTE discovered it";
  s.client.Say("INVALIDATEROUTE {To m2}");
  const auto answer = s.RunUntilLine("INVALIDATED", 4);
  ASSERT_TRUE(answer);
  EXPECT_EQ(*answer->Get("Done"), "True");
  EXPECT_FALSE(valid_route());
  s.client.Say("INVALIDATEROUTE {To nobody}");
  const auto refused = s.RunUntilLine("ERR", 5);
  ASSERT_TRUE(refused);
  EXPECT_NE(refused->Get("Message")->find("INVALIDATEROUTE"), std::string::npos);
  s.client.Say("REQUESTROUTE {To r}");
  const auto itself = s.RunUntilLine("ERR", 6);
  ASSERT_TRUE(itself);
  EXPECT_EQ(*itself->Get("Message"), "REQUESTROUTE (To r): that is this robot");
  s.world.Finish();
}

TEST(NetworkView, ARobotWithoutATapIsToldToReadItsKernel) {
  Served s(MoteLineWithRobot(), false);
  s.RunTo(0.5);
  s.client.Say("GETNET");
  const auto net = s.RunUntilLine("NET", 1);
  ASSERT_TRUE(net);
  EXPECT_EQ(*net->Get("Source"), "Kernel");
  EXPECT_FALSE(net->Get("Route"));
  s.world.Finish();
}

usarsim_agent::Ipv4 Address(const char* text) { return ::inet_addr(text); }

TEST(KernelTables, RoutesAndNeighboursMapToNodesThroughTheirAddresses) {
  const std::vector<std::optional<usarsim_agent::Ipv4>> addresses = {Address("10.1.0.1"), Address("10.1.0.2"),
                                                                     Address("10.1.0.3"), std::nullopt};
  const std::vector<usarsim_agent::KernelRoute> routes = {
      {Address("10.1.0.2"), std::nullopt},         // direct
      {Address("10.1.0.3"), Address("10.1.0.2")},  // through node 1
      {Address("10.9.9.9"), std::nullopt},         // no node's
  };
  const std::vector<usarsim_agent::KernelNeighbour> neighbours = {{Address("10.1.0.2")}, {Address("192.168.1.1")}};
  const usarsim_agent::KernelTables t = usarsim_agent::MapToNodes(0, addresses, routes, neighbours);
  ASSERT_EQ(t.routes.size(), 2u);
  EXPECT_EQ(t.routes[0].destination, 1u);
  EXPECT_EQ(t.routes[0].next_hop, 1u);
  EXPECT_EQ(t.routes[0].hops, 1);
  EXPECT_EQ(t.routes[1].destination, 2u);
  EXPECT_EQ(t.routes[1].next_hop, 1u);
  EXPECT_EQ(t.routes[1].hops, 2);
  EXPECT_TRUE(t.routes[1].valid);
  EXPECT_EQ(t.neighbours, std::vector<NodeId>{1});
}

TEST(KernelTables, ARouteThroughAGatewayThatIsNoNodeIsLeftOut) {
  const std::vector<std::optional<usarsim_agent::Ipv4>> addresses = {Address("10.1.0.1"), Address("10.2.0.1")};
  const usarsim_agent::KernelTables t =
      usarsim_agent::MapToNodes(0, addresses, {{Address("10.2.0.1"), Address("10.1.0.254")}}, {});
  EXPECT_TRUE(t.routes.empty());
}

TEST(KernelTables, OnLoopbackEveryAgentSharesAnAddressAndTheTablesAreEmpty) {
  const std::vector<std::optional<usarsim_agent::Ipv4>> addresses = {Address("127.0.0.1"), Address("127.0.0.1"),
                                                                     Address("127.0.0.1")};
  const usarsim_agent::KernelTables t = usarsim_agent::ReadKernelTables(0, addresses);
  EXPECT_TRUE(t.routes.empty());
  EXPECT_TRUE(t.neighbours.empty());
  // The kernel itself answers: this machine has a route to its own loopback address.
  const auto route = usarsim_agent::KernelRouteTo(Address("127.0.0.1"));
  ASSERT_TRUE(route);
  EXPECT_FALSE(route->gateway);
}

}  // namespace
}  // namespace sanet
