// The run as a whole: one clock, ns-3 mobility reading physics, messages, failures, outputs.
#include <gtest/gtest.h>
#include <ns3/mobility-model.h>
#include <ns3/node-list.h>
#include <ns3/node.h>
#include <ns3/simulator.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "sim/assembly.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

TEST(World, Ns3MobilityAnswersWithThePhysicsPoseAtTheTimeItAsks) {
  sim::World world(
      Spec(4, {Robot("r", ModelKind::kOmni3, {0, 0, 0}, UseController("constant_velocity", {{"vx", Scalar(0.5)}}))}),
      BuiltinRegistry());
  std::vector<std::pair<ns3::Vector, Pose2D>> samples;
  world.Observe([&](const sim::WorldSnapshot& snapshot) {
    const double t = snapshot.time();
    if (std::fmod(t, 1.0) < 1e-9) {
      auto mobility = ns3::NodeList::GetNode(0)->GetObject<ns3::MobilityModel>();
      samples.emplace_back(mobility->GetPosition(), world.model(0).body().pose());
    }
  });
  world.Run({});
  ASSERT_GE(samples.size(), 3u);
  for (const auto& [ns3_pos, pose] : samples) {
    EXPECT_DOUBLE_EQ(ns3_pos.x, pose.x);
    EXPECT_DOUBLE_EQ(ns3_pos.y, pose.y);
  }
  EXPECT_GT(samples.back().first.x, 1.0) << "the robot moved and ns-3 saw it";
}

// Replies to every message with the same payload plus one byte; records what it got.
class Echo : public Controller {
 public:
  explicit Echo(std::vector<Message>* inbox, bool starter) : inbox_(inbox), starter_(starter) {}
  void Start(Node& node) override {
    if (starter_) node.Send(*node.Lookup("b"), Bytes{1});
  }
  void ControlStep(Node&) override {}
  void OnMessage(Node& node, const Message& m) override {
    inbox_->push_back(m);
    if (m.payload.size() < 4) {
      Bytes reply = m.payload;
      reply.push_back(static_cast<std::uint8_t>(reply.size() + 1));
      node.Send(m.from, reply);
    }
  }

 private:
  std::vector<Message>* inbox_;
  bool starter_;
};

TEST(World, MessagesTravelBetweenControllersOnTheSimulationClock) {
  hosting::Registry registry;
  std::vector<Message> inbox_a, inbox_b;
  registry.Add({"echo_a", "", [&](const Params&) { return std::make_unique<Echo>(&inbox_a, true); }});
  registry.Add({"echo_b", "", [&](const Params&) { return std::make_unique<Echo>(&inbox_b, false); }});
  sim::RunSpec spec = Spec(1, {Robot("a", ModelKind::kMote, {0, 0, 0}, UseController("echo_a", {})),
                               Robot("b", ModelKind::kMote, {5, 0, 0}, UseController("echo_b", {}))});
  spec.message_latency = 0.01;
  sim::World world(spec, registry);
  world.Run({});
  ASSERT_EQ(inbox_b.size(), 2u);
  ASSERT_EQ(inbox_a.size(), 2u);
  EXPECT_EQ(inbox_b[0].from, 0u);
  EXPECT_EQ(inbox_b[0].payload, Bytes{1});
  EXPECT_NEAR(inbox_b[0].time_received - inbox_b[0].time_sent, 0.01, 1e-9);
  EXPECT_EQ(inbox_a[1].payload, (Bytes{1, 2, 3, 4}));
  EXPECT_NEAR(inbox_a[1].time_received, 0.04, 1e-9);
}

class Thrower : public Controller {
 public:
  void ControlStep(Node& node) override {
    if (node.Now() > 0.5) throw std::runtime_error("sensor exploded");
  }
};

TEST(World, AFailingControllerEndsTheRunButKeepsItsResults) {
  hosting::Registry registry;
  registry.Add({"thrower", "", [](const Params&) { return std::make_unique<Thrower>(); }});
  const std::string dir = ::testing::TempDir() + "/sanet-failing-run";
  std::filesystem::remove_all(dir);
  sim::World world(Spec(10, {Robot("r", ModelKind::kOmni3, {0, 0, 0}, UseController("thrower", {}))}), registry);
  try {
    world.Run({dir, "test"});
    FAIL() << "the failure was not reported";
  } catch (const sim::WorldError& e) {
    EXPECT_NE(std::string(e.what()).find("sensor exploded"), std::string::npos);
  }
  const std::string summary = ReadFile(dir + "/summary.json");
  EXPECT_NE(summary.find("failed: controller of r failed: sensor exploded"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"ended_by\": \"controller failure\""), std::string::npos) << summary;
  EXPECT_NE(ReadFile(dir + "/trajectories.csv").find("0.000,r,"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir + "/trajectories.csv.tmp"));
}

struct PluginOwnError {};  // not a std::exception

// A plugin may throw anything: an int, a string, its own type. The run ends all the same, its
// results kept and the cause named.
TEST(World, AControllerThrowingAnythingEndsTheRunNamingWhatItThrew) {
  const std::vector<std::pair<std::function<void()>, std::string>> throws = {
      {[] { throw 42; }, "an exception of type int"},
      {[] { throw std::string("out of cheese"); }, "out of cheese"},
      {[] { throw PluginOwnError{}; }, "an exception of type sanet::(anonymous namespace)::PluginOwnError"}};
  for (const auto& [thrower, named] : throws) {
    struct Throws : Controller {
      std::function<void()> what;
      void ControlStep(Node& node) override {
        if (node.Now() > 0.2) what();
      }
    };
    hosting::Registry registry;
    registry.Add({"throws", "", [&, thrower = thrower](const Params&) {
                    auto c = std::make_unique<Throws>();
                    c->what = thrower;
                    return c;
                  }});
    const std::string dir = ::testing::TempDir() + "/sanet-throws-anything";
    std::filesystem::remove_all(dir);
    sim::World world(Spec(10, {Robot("r", ModelKind::kOmni3, {0, 0, 0}, UseController("throws", {}))}), registry);
    EXPECT_THROW(world.Run({dir, "test"}), sim::WorldError);
    const std::string summary = ReadFile(dir + "/summary.json");
    EXPECT_NE(summary.find("failed: controller of r failed: " + named), std::string::npos) << summary;
    EXPECT_NE(ReadFile(dir + "/trajectories.csv").find("0.000,r,"), std::string::npos);
  }
}

// A controller's text may be any bytes: a log line, a state name, a reason, a metric's name that
// are not UTF-8 cost the run nothing, and summary.json stays valid JSON (nlohmann's parser
// refuses invalid UTF-8, so parsing it is the check).
TEST(World, TextThatIsNotUtf8LeavesAValidSummary) {
  struct Babble : Controller {
    void ControlStep(Node& node) override {
      node.Log("caf\xe9 \xff\xfe log");
      node.Transition("idle", "st\xc3\x28te", "because \xa0\xa1");
      node.Metric("m\xe9tric", 1.5);
    }
  };
  hosting::Registry registry;
  registry.Add({"babble", "", [](const Params&) { return std::make_unique<Babble>(); }});
  const std::string dir = ::testing::TempDir() + "/sanet-not-utf8";
  std::filesystem::remove_all(dir);
  sim::World world(Spec(1, {Robot("r", ModelKind::kOmni3, {0, 0, 0}, UseController("babble", {}))}), registry);
  world.Run({dir, "test"});
  const auto summary = nlohmann::json::parse(ReadFile(dir + "/summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_TRUE(summary["metrics"]["r"].contains("m\xef\xbf\xbdtric")) << summary["metrics"].dump();
  EXPECT_NE(ReadFile(dir + "/log.csv").find("caf\xe9 \xff\xfe log"), std::string::npos) << "the CSV keeps the bytes";
}

// Drives forward, then asks for a NaN velocity and infinite wheel speeds; records the answers.
class NotANumber : public Controller {
 public:
  std::vector<bool>* answers;
  explicit NotANumber(std::vector<bool>* a) : answers(a) {}
  void ControlStep(Node& node) override {
    if (node.Now() < 0.05) return answers->push_back(node.Drive({0.3, 0, 0}));
    if (answers->size() == 1) answers->push_back(node.Drive({std::nan(""), 0, 0}));
    if (answers->size() == 2) answers->push_back(node.SetWheelSpeeds({HUGE_VAL, 1, 1}));
  }
};

TEST(World, ANonFiniteCommandIsRefusedLoggedAndTheMotorsKeepTheLastOne) {
  std::vector<bool> answers;
  hosting::Registry registry;
  registry.Add({"nan", "", [&answers](const Params&) { return std::make_unique<NotANumber>(&answers); }});
  const std::string dir = ::testing::TempDir() + "/sanet-nan-drive";
  std::filesystem::remove_all(dir);
  sim::World world(Spec(2, {Robot("r", ModelKind::kOmni3, {0, 0, 0}, UseController("nan", {}))}), registry);
  world.Run({dir, "test"});
  EXPECT_EQ(answers, (std::vector<bool>{true, false, false}));
  const std::string log = ReadFile(dir + "/log.csv");
  EXPECT_NE(log.find("drive refused: a velocity that is not a finite number"), std::string::npos) << log;
  EXPECT_NE(log.find("wheel speeds refused"), std::string::npos) << log;
  EXPECT_GT(world.parts().model(0).body().pose().x, 0.3);  // still driving at 0.3 m/s after 2 s
}

TEST(World, OnlyOneWorldAtATime) {
  sim::World world(Spec(1, {Robot("m", ModelKind::kMote, {0, 0, 0})}), BuiltinRegistry());
  EXPECT_THROW(sim::World(Spec(1, {Robot("m", ModelKind::kMote, {0, 0, 0})}), BuiltinRegistry()), sim::WorldError);
}

TEST(World, WritesTrajectoriesForMovingNodesAndOnceForRestingOnes) {
  const std::string dir = ::testing::TempDir() + "/sanet-outputs";
  std::filesystem::remove_all(dir);
  sim::World world(
      Spec(2, {Robot("r", ModelKind::kOmni3, {0, 0, 0}, UseController("constant_velocity", {{"vx", Scalar(0.3)}})),
               Robot("m", ModelKind::kMote, {5, 5, 0})}),
      BuiltinRegistry());
  const sim::RunResult r = world.Run({dir, "test"});
  const std::string csv = ReadFile(dir + "/trajectories.csv");
  std::size_t robot_rows = 0, mote_rows = 0;
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "time,node,x,y,theta");
  while (std::getline(lines, line)) {
    robot_rows += line.find(",r,") != std::string::npos;
    mote_rows += line.find(",m,") != std::string::npos;
  }
  EXPECT_EQ(robot_rows, 21u) << "every 0.1 s from 0 to 2 s";
  EXPECT_EQ(mote_rows, 2u) << "the start and the final pose";
  EXPECT_EQ(r.physics_steps, 400u);
  EXPECT_GT(r.events, r.physics_steps);
  EXPECT_NE(ReadFile(dir + "/summary.json").find("\"fingerprint\": \"" + r.fingerprint + "\""), std::string::npos);
}

}  // namespace
}  // namespace sanet
