// The help-request case study: the robot reaches the target through the network, around the
// wall, hop by hop from its routing table; every timeout and retry path of both machines.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenario/scenario_loader.h"
#include "sensors/bearing/bearing.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

struct Transition {
  double time;
  std::string node, from, to, why;
};

std::vector<Transition> Transitions(const std::string& dir) {
  std::vector<Transition> out;
  std::istringstream lines(ReadFile(dir + "/transitions.csv"));
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line)) {
    std::vector<std::string> f;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) f.push_back(cell);
    while (f.size() > 5) f[4] += "," + f[5], f.erase(f.begin() + 5);
    out.push_back({std::stod(f[0]), f[1], f[2], f[3], f.size() > 4 ? f[4] : ""});
  }
  return out;
}

const Transition* Find(const std::vector<Transition>& all, const std::string& node, const std::string& to,
                       const std::string& why_part = "") {
  for (const Transition& t : all)
    if (t.node == node && t.to == to && t.why.find(why_part) != std::string::npos) return &t;
  return nullptr;
}

std::string RunIn(const std::string& tag, const sim::RunSpec& spec, hosting::Registry& registry = BuiltinRegistry()) {
  const std::string dir = ::testing::TempDir() + "/sanet-help-" + tag;
  std::filesystem::remove_all(dir);
  sim::World world(spec, registry);
  world.Run({dir, ""});
  return dir;
}

// The shipped scenario shrunk: 60 m between motes and 20 dBm radios (70 m range) keep it
// multi-hop and the wall in the robot's way, in a tenth of the time.
sim::RunSpec SmallHelpRequest() {
  sim::RunSpec spec = scenario::LoadScenario(SANET_SOURCE_DIR "/scenarios/help-request.yaml").run;
  const double k = 60.0 / 125.0;
  for (auto& n : spec.nodes) n.pose.x *= k, n.pose.y *= k;
  for (auto& o : spec.obstacles) o.box.center.x *= k, o.box.center.y *= k, o.box.size.x *= k;
  spec.network->tx_power = 20;
  SensorSettings<sensors::BearingSettings>(spec.nodes.back(), "bearing").range = 70;
  spec.figures = true;
  return spec;
}

TEST(HelpRequest, TheRobotArrivesAroundTheWall) {
  sim::RunSpec spec = SmallHelpRequest();
  hosting::Registry& registry = BuiltinRegistry();
  const std::string dir = ::testing::TempDir() + "/sanet-help-base";
  std::filesystem::remove_all(dir);
  double closest = 1e9;
  {
    sim::World world(spec, registry);
    const NodeId robot = *world.Lookup("robot");
    world.Observe([&](const sim::WorldSnapshot&) {
      closest = std::min(closest, DistanceToBox(world.model(robot).body().pose().position(), spec.obstacles[0].box));
    });
    world.Run({dir, ""});
  }
  const auto transitions = Transitions(dir);
  ASSERT_TRUE(Find(transitions, "robot", "arrived")) << ReadFile(dir + "/transitions.csv");
  EXPECT_TRUE(Find(transitions, "target", "done", "arrived"));
  EXPECT_GT(closest, 0.19) << "the robot's body never overlaps the wall";
  // Every hop it chose was reached, and there were several.
  int hops = 0;
  for (const Transition& t : transitions) hops += t.to == "go_to_next_hop";
  EXPECT_GE(hops, 6);
  EXPECT_NE(ReadFile(dir + "/summary.json").find("\"time_avoiding_obstacles\""), std::string::npos);
  const std::string map = ReadFile(dir + "/map.svg");
  EXPECT_EQ(map.rfind("<?xml", 0), 0u);
  EXPECT_NE(map.find("<polyline"), std::string::npos);
  EXPECT_NE(map.find("50 s</text>"), std::string::npos) << "time marks on the trajectory";
  EXPECT_NE(ReadFile(dir + "/packets.svg").find(">packets received</text>"), std::string::npos) << "the colour scale";
}

// Passes every call to the real node, remembering the routing table it handed out, and checks
// each next hop the controller announces against that table.
class TableWitness : public Node {
 public:
  TableWitness(Node& inner, std::vector<std::string>* violations, int* checked)
      : inner_(inner), violations_(violations), checked_(checked) {}
  double Now() const override { return inner_.Now(); }
  NodeId Id() const override { return inner_.Id(); }
  const std::string& Name() const override { return inner_.Name(); }
  std::optional<NodeId> Lookup(const std::string& n) const override { return inner_.Lookup(n); }
  std::string NameOf(NodeId id) const override { return inner_.NameOf(id); }
  std::size_t NodeCount() const override { return inner_.NodeCount(); }
  std::optional<SensorReading> Sensor(const std::string& name) override { return inner_.Sensor(name); }
  bool SetRadioSleep(bool asleep) override { return inner_.SetRadioSleep(asleep); }
  std::optional<BearingReading> Bearing(NodeId t) override { return inner_.Bearing(t); }
  bool ApplyDrive(const Twist2D& v) override { return inner_.Drive(v); }
  bool ApplyWheelSpeeds(const std::vector<double>& w) override { return inner_.SetWheelSpeeds(w); }
  bool Holonomic() const override { return inner_.Holonomic(); }
  void Send(NodeId to, const Bytes& p) override { inner_.Send(to, p); }
  void Broadcast(const Bytes& p) override { inner_.Broadcast(p); }
  void Flood(const Bytes& p) override { inner_.Flood(p); }
  double Random() override { return inner_.Random(); }
  NetworkView& Network() override { return view_; }
  void Log(const std::string& text) override { inner_.Log(text); }
  void Metric(const std::string& name, double value) override { inner_.Metric(name, value); }
  // find_next_hop -> go_to_next_hop, why "next hop m5 of 1 towards target"
  void Transition(const std::string& from, const std::string& to, const std::string& why) override {
    if (from == "find_next_hop" && why.rfind("next hop ", 0) == 0) {
      std::istringstream words(why.substr(9));
      std::string hop, of, count, towards, dest;
      words >> hop >> of >> count >> towards >> dest;
      const NodeId h = *Lookup(hop), d = *Lookup(dest);
      bool listed = false;
      for (const RouteEntry& e : view_.last) listed = listed || (e.valid && e.destination == d && e.next_hop == h);
      if (!listed) violations_->push_back(why);
      ++*checked_;
    }
    inner_.Transition(from, to, why);
  }

 private:
  struct View : NetworkView {
    NetworkView* inner = nullptr;
    std::vector<RouteEntry> last;
    std::string Protocol() const override { return inner->Protocol(); }
    std::vector<RouteEntry> RoutingTable() const override {
      const_cast<View*>(this)->last = inner->RoutingTable();
      return last;
    }
    std::vector<NodeId> Neighbours() const override { return inner->Neighbours(); }
    bool InvalidateRoute(NodeId d) override { return inner->InvalidateRoute(d); }
    void RequestRoute(NodeId d) override { inner->RequestRoute(d); }
  };
  Node& inner_;
  std::vector<std::string>* violations_;
  int* checked_;
  View view_;

 public:
  void Bind() { view_.inner = &inner_.Network(); }
};

class Witnessed : public Controller {
 public:
  Witnessed(std::unique_ptr<Controller> inner, std::vector<std::string>* v, int* c)
      : inner_(std::move(inner)), violations_(v), checked_(c) {}
  void Start(Node& node) override { inner_->Start(Wrap(node)); }
  void ControlStep(Node& node) override { inner_->ControlStep(Wrap(node)); }
  void OnMessage(Node& node, const Message& m) override { inner_->OnMessage(Wrap(node), m); }

 private:
  Node& Wrap(Node& node) {
    if (!witness_) {
      witness_ = std::make_unique<TableWitness>(node, violations_, checked_);
      witness_->Bind();
    }
    return *witness_;
  }
  std::unique_ptr<Controller> inner_;
  std::unique_ptr<TableWitness> witness_;
  std::vector<std::string>* violations_;
  int* checked_;
};

TEST(HelpRequest, EveryHopWasANextHopInTheRobotsRoutingTableWhenChosen) {
  hosting::Registry registry;
  controllers::RegisterBuiltinControllers(registry);
  std::vector<std::string> violations;
  int checked = 0;
  registry.Add({"witnessed_robot", "", [&](const Params& p) {
                  return std::make_unique<Witnessed>(registry.Find("help_request_robot")->create(p), &violations,
                                                     &checked);
                }});
  sim::RunSpec spec = SmallHelpRequest();
  spec.nodes.back().controller->name = "witnessed_robot";
  const std::string dir = RunIn("witness", spec, registry);
  EXPECT_TRUE(Find(Transitions(dir), "robot", "arrived"));
  EXPECT_GE(checked, 6);
  EXPECT_TRUE(violations.empty()) << violations.front();
}

TEST(HelpRequest, TheRobotGivesUpWhenTheTargetIsSwitchedOffOnTheWay) {
  sim::RunSpec spec = SmallHelpRequest();
  spec.events.push_back(
      {150, static_cast<std::uint32_t>(spec.nodes.size() - 2), sim::NodeEvent::Action::kSwitchOff, std::nullopt});
  spec.duration = 700;
  const auto transitions = Transitions(RunIn("switched-off", spec));
  EXPECT_FALSE(Find(transitions, "robot", "arrived"));
  const Transition* gave_up = Find(transitions, "robot", "idle", "gave up");
  ASSERT_TRUE(gave_up) << "the robot should give up";
  EXPECT_GT(gave_up->time, 150);
}

// Without a network every message reaches every node at once: enough for the state machines.
sim::RunSpec Local(double duration) {
  sim::RunSpec spec;
  spec.duration = duration;
  spec.message_latency = 0.01;
  return spec;
}

sim::NodeSpec HelpMote(const std::string& name, double request_at, Vec2 at = {0, 0}) {
  return Robot(name, ModelKind::kMote, {at.x, at.y, 0},
               UseController("help_request_mote", {{"request_at", Scalar(request_at)}}));
}

sim::NodeSpec HelpRobot(const std::string& name, Vec2 at, double hop_time = 300) {
  sim::NodeSpec n = Robot(name, ModelKind::kOmni3, {at.x, at.y, 0},
                          UseController("help_request_robot", {{"hop_time", Scalar(hop_time)}}));
  n.model.sensors["bearing"] = {"bearing", sensors::BearingSettings{100, 0, 0}};
  return n;
}

TEST(HelpRequest, AMoteNobodyAnswersRequestsThreeTimesAndGivesUp) {
  sim::RunSpec spec = Local(200);
  spec.nodes = {HelpMote("target", 5)};
  const auto t = Transitions(RunIn("unanswered", spec));
  const Transition* gave_up = Find(t, "target", "gave_up", "3 requests");
  ASSERT_TRUE(gave_up);
  EXPECT_NEAR(gave_up->time, 5 + 3 * 30, 0.2);
}

TEST(HelpRequest, ARobotWithoutAnswerAsksThreeTimesAndGivesUp) {
  sim::RunSpec spec = Local(200);
  spec.nodes = {HelpMote("target", 5, {20, 0}), HelpRobot("robot", {0, 0})};
  spec.events.push_back({5.005, 0, sim::NodeEvent::Action::kSwitchOff, std::nullopt});  // right after its request
  const auto t = Transitions(RunIn("no-answer", spec));
  ASSERT_TRUE(Find(t, "robot", "request_assignment"));
  const Transition* gave_up = Find(t, "robot", "idle", "no answer from target after 3");
  ASSERT_TRUE(gave_up);
  EXPECT_NEAR(gave_up->time, 5 + 3 * 30, 0.5);
}

TEST(HelpRequest, AMoteDropsASilentRobotAndRequestsAgain) {
  sim::RunSpec spec = Local(100);
  spec.nodes = {HelpMote("target", 5, {60, 0}), HelpRobot("robot", {0, 0}, /*hop_time=*/20)};
  spec.events.push_back({8, 1, sim::NodeEvent::Action::kSwitchOff, std::nullopt});  // after it took the request
  const std::string dir = RunIn("silent", spec);
  const auto t = Transitions(dir);
  ASSERT_TRUE(Find(t, "target", "wait", "takes the request"));
  const Transition* dropped = Find(t, "target", "request", "silent past its hop time");
  ASSERT_TRUE(dropped);
  // The mote waits one hop time (20 s) after the last message it got from the robot.
  double last = 0;
  std::istringstream rows(ReadFile(dir + "/messages.csv"));
  for (std::string row; std::getline(rows, row);) {
    std::vector<std::string> f;  // time_sent,from,to,delivery,bytes,time_received,delay,hops
    std::stringstream cells(row);
    for (std::string cell; std::getline(cells, cell, ',');) f.push_back(cell);
    if (f.size() >= 6 && f[1] == "robot" && f[2] == "target") last = std::stod(f[5]);
  }
  ASSERT_GT(last, 0);
  EXPECT_LT(last, 8.01);
  EXPECT_NEAR(dropped->time, last + 20, 0.15);
}

TEST(HelpRequest, AMoteRefusesASecondRobot) {
  sim::RunSpec spec = Local(30);
  spec.nodes = {HelpMote("target", 5, {60, 0}), HelpRobot("first", {0, 0}), HelpRobot("second", {0, 5})};
  const std::string dir = RunIn("refuse", spec);
  const auto t = Transitions(dir);
  ASSERT_TRUE(Find(t, "target", "wait", "first takes the request"));
  EXPECT_TRUE(Find(t, "second", "idle", "target refused"));
  EXPECT_NE(ReadFile(dir + "/log.csv").find("refuse robot second: another robot is in charge"), std::string::npos);
}

}  // namespace
}  // namespace sanet
