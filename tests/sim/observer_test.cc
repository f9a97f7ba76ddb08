// Observers of a run: each sees a read-only snapshot after every step, built lazily, the same
// for all of them.
#include <gtest/gtest.h>

#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

// Sends to the other robot every step and changes state once, at 1 s.
class Chatter : public Controller {
 public:
  void ControlStep(Node& node) override {
    node.Drive({0.3, 0, 0.2});
    node.Send(node.Id() == 0 ? 1 : 0, Bytes(32, 7));
    if (node.Now() >= 1 && !moved_) {
      node.Transition("idle", "chatting", "one second passed");
      moved_ = true;
    }
  }

 private:
  bool moved_ = false;
};

struct Seen {
  double time;
  std::uint64_t step;
  std::vector<Pose2D> poses;
  std::vector<std::vector<NodeId>> neighbours;
  std::size_t in_flight;
  std::vector<std::string> states;
};

class Recorder {
 public:
  void Observe(sim::RunBus& bus) {
    heard_ = bus.On<sim::StepEnded>(sim::RunStage::kObserve, [this](const sim::StepEnded& e) { AfterStep(e.world); });
  }
  void AfterStep(const sim::WorldSnapshot& s) {
    Seen seen{s.time(), s.step(), {}, s.radio_neighbours(), s.messages_in_flight().size(), s.controller_states()};
    for (const sim::BodyState& b : s.bodies()) seen.poses.push_back(b.pose);
    log.push_back(seen);
  }
  std::vector<Seen> log;

 private:
  Subscription heard_;
};

sim::RunSpec TwoChattingRobots() {
  hosting::Registry& registry = BuiltinRegistry();
  if (!registry.Find("test_chatter"))
    registry.Add({"test_chatter", "", [](const Params&) { return std::make_unique<Chatter>(); }});
  sim::RunSpec spec = Spec(2, {Robot("a", ModelKind::kDiffDrive, {0, 0, 0}, UseController("test_chatter", {})),
                               Robot("b", ModelKind::kDiffDrive, {30, 0, 0}, UseController("test_chatter", {}))});
  spec.network = net::NetworkSpec{};
  return spec;
}

TEST(Observers, TwoObserversSeeTheSameSnapshots) {
  sim::World world(TwoChattingRobots(), BuiltinRegistry());
  Recorder first, second;
  first.Observe(world.bus());
  second.Observe(world.bus());
  world.Run({});
  ASSERT_EQ(first.log.size(), 400u);  // 2 s of 5 ms steps
  ASSERT_EQ(first.log.size(), second.log.size());
  for (std::size_t i = 0; i < first.log.size(); ++i) {
    const Seen &a = first.log[i], &b = second.log[i];
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.step, i + 1);
    EXPECT_EQ(a.step, b.step);
    for (std::size_t n = 0; n < 2; ++n) {
      EXPECT_EQ(a.poses[n].x, b.poses[n].x);
      EXPECT_EQ(a.poses[n].theta, b.poses[n].theta);
    }
    EXPECT_EQ(a.neighbours, b.neighbours);
    EXPECT_EQ(a.in_flight, b.in_flight);
    EXPECT_EQ(a.states, b.states);
  }
}

TEST(Observers, SnapshotsShowTheWorldAsItIsAfterTheStep) {
  sim::World world(TwoChattingRobots(), BuiltinRegistry());
  std::size_t steps_with_messages_in_flight = 0, checked = 0;
  std::vector<std::string> last_states;
  world.Observe([&](const sim::WorldSnapshot& s) {
    for (NodeId id = 0; id < 2; ++id) {
      EXPECT_EQ(s.bodies()[id].pose.x, world.model(id).body().pose().x);
      ++checked;
    }
    steps_with_messages_in_flight += !s.messages_in_flight().empty();
    if (s.time() < 0.99) {
      EXPECT_EQ(s.controller_states()[0], "");
    }
    last_states = s.controller_states();
  });
  world.Run({});
  EXPECT_EQ(checked, 800u);
  EXPECT_GT(steps_with_messages_in_flight, 0u) << "messages take time over the radio";
  EXPECT_EQ(last_states, (std::vector<std::string>{"chatting", "chatting"}));
}

TEST(Observers, NeighboursComeFromTheRoutingLayer) {
  sim::World world(TwoChattingRobots(), BuiltinRegistry());
  std::vector<NodeId> neighbours_of_a;
  world.Observe([&](const sim::WorldSnapshot& s) { neighbours_of_a = s.radio_neighbours()[0]; });
  world.Run({});
  EXPECT_EQ(neighbours_of_a, std::vector<NodeId>{1}) << "30 m apart, AODV hellos make them neighbours";
}

}  // namespace
}  // namespace sanet
