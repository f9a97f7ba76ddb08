// The physics thread: steps run in order on their own thread, whatever touches the world waits for
// them, and a step's failure reaches the thread that waits.
#include "physics/pipelined_world.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace sanet::physics {
namespace {

TEST(StepWorker, RunsWorkInLaunchOrderOnAnotherThread) {
  StepWorker worker(/*threaded=*/true, /*depth=*/4);
  std::vector<int> order;
  std::vector<std::thread::id> ran_on;
  for (int i = 0; i < 100; ++i)
    EXPECT_EQ(worker.Launch([&, i] {
      order.push_back(i);
      ran_on.push_back(std::this_thread::get_id());
    }),
              static_cast<std::uint64_t>(i + 1));
  worker.Wait();
  ASSERT_EQ(order.size(), 100u);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(order[i], i);
  for (const auto& id : ran_on) EXPECT_NE(id, std::this_thread::get_id());
}

TEST(StepWorker, WaitForReturnsOnceThatPieceIsDoneWithoutWaitingForLaterOnes) {
  StepWorker worker(true, 4);
  std::atomic<bool> release{false}, second_started{false};
  worker.Launch([] {});
  worker.Launch([&] {
    second_started = true;
    while (!release) std::this_thread::yield();
  });
  worker.WaitFor(1);  // must not block on the second piece, which waits for us
  while (!second_started) std::this_thread::yield();
  release = true;
  worker.Wait();
}

TEST(StepWorker, AFailureInTheWorkIsRethrownWhereTheLauncherWaits) {
  StepWorker worker(true, 2);
  worker.Launch([] { throw std::runtime_error("step failed"); });
  EXPECT_THROW(worker.Wait(), std::runtime_error);
}

TEST(StepWorker, WithoutAThreadTheWorkRunsAtOnce) {
  StepWorker worker(false, 4);
  bool ran = false;
  worker.Launch([&] { ran = true; });
  EXPECT_TRUE(ran);
  EXPECT_FALSE(worker.threaded());
}

TEST(StepWorker, SleepsWhenIdleAndWakesForTheNextPiece) {
  StepWorker worker(true, 2);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // past its spin: asleep
  bool ran = false;
  worker.Launch([&] { ran = true; });
  worker.Wait();
  EXPECT_TRUE(ran);
}

// A body read while a step is queued sees the state after it, on either engine.
class PipelinedWorldOn : public ::testing::TestWithParam<Engine> {};

TEST_P(PipelinedWorldOn, ABodyReadWaitsForTheStepsStarted) {
  WorldSettings settings;
  settings.engine = GetParam();
  PipelinedWorld threaded(GetParam() == Engine::k2d ? CreateBox2dWorld(settings) : CreateOdeWorld(settings), true, 8);
  PipelinedWorld inline_world(GetParam() == Engine::k2d ? CreateBox2dWorld(settings) : CreateOdeWorld(settings), false,
                              8);
  Vehicle* a = threaded.add_diffdrive({}, {0, 0, 0});
  Vehicle* b = inline_world.add_diffdrive({}, {0, 0, 0});
  for (Vehicle* v : {a, b}) v->set_wheel_speed(0, 5), v->set_wheel_speed(1, 5);
  for (int i = 0; i < 200; ++i) {
    threaded.StepAsync([&] { threaded.step(0.01); });
    inline_world.StepAsync([&] { inline_world.step(0.01); });
  }
  const Pose2D pa = a->pose(), pb = b->pose();
  EXPECT_GT(pa.x, 0.5);  // it drove
  EXPECT_EQ(pa.x, pb.x);
  EXPECT_EQ(pa.y, pb.y);
  EXPECT_EQ(pa.theta, pb.theta);
  // A ray cast ignores the gated body as the engine's own would.
  EXPECT_DOUBLE_EQ(threaded.cast_ray({pa.x, pa.y, 0.1}, {1, 0, 0}, 5, a), 5);
}

INSTANTIATE_TEST_SUITE_P(Engines, PipelinedWorldOn, ::testing::Values(Engine::k3d, Engine::k2d),
                         [](const auto& info) { return info.param == Engine::k3d ? "Ode3d" : "Box2d"; });

}  // namespace
}  // namespace sanet::physics
