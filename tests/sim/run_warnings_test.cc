// What a run's reader should know although nothing failed reaches summary.json's "warnings" and
// the run's result, never log.csv: the physics engine's messages (raised here through ODE's own
// message hook, as ODE raises "LCP internal error"), with the bodies in contact when the first
// came, and motes that a robot pushed away.
#include <gtest/gtest.h>
#include <ode/ode.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/test_world.h"

namespace sanet {
namespace {

using robots::ModelKind;

// Drives forward; from `at` s on, says what ODE says when bodies are stuck in each other.
class PushAndComplain : public Controller {
 public:
  explicit PushAndComplain(double at) : at_(at) {}
  void ControlStep(Node& node) override {
    node.Drive({0.4, 0, 0});
    if (at_ >= 0 && node.Now() >= at_) dMessage(3, "LCP internal error, s <= 0 (s=%.4e)", -1.5e-7);
  }

 private:
  double at_;
};

hosting::Registry& Registry() {
  static hosting::Registry* registry = [] {
    auto* r = new hosting::Registry;
    r->Add({"push_and_complain", "",
            [](const Params& p) { return std::make_unique<PushAndComplain>(p.Number("complain_at", -1, -1, 1e6)); }});
    return r;
  }();
  return *registry;
}

// A robot that drives 1 m into a wall, with a mote in its way.
sim::RunSpec IntoTheWall(double complain_at) {
  sim::RunSpec spec = testing::Spec(
      4, {testing::Robot("r1", ModelKind::kOmni3, {0, 0, 0},
                         testing::UseController("push_and_complain", {{"complain_at", testing::Scalar(complain_at)}})),
          testing::Robot("m0", ModelKind::kMote, {0.5, 0, 0})});
  spec.obstacles.push_back(testing::Box({1.4, 0}, 0.2, 4, 1));
  return spec;
}

nlohmann::json RunInto(const std::string& dir, double complain_at, std::string* fingerprint) {
  std::filesystem::remove_all(dir);
  sim::World world(IntoTheWall(complain_at), Registry());
  sim::RunOptions options;
  options.output_dir = dir;
  const sim::RunResult r = world.Run(options);
  *fingerprint = r.fingerprint;
  std::ifstream in(dir + "/summary.json");
  nlohmann::json summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["warnings"], nlohmann::json(r.warnings));
  return summary;
}

TEST(RunWarnings, AnEngineMessageIsAWarningNamingTheBodiesInContact) {
  const std::string dir = ::testing::TempDir() + "/warnings-ode";
  std::string fingerprint, quiet_fingerprint;
  const nlohmann::json summary = RunInto(dir, 3.0, &fingerprint);
  ASSERT_GE(summary["warnings"].size(), 1u);
  const std::string first = summary["warnings"][0];
  EXPECT_NE(first.find("ODE message 3: LCP internal error, s <= 0 (s=-1.5000e-07)"), std::string::npos) << first;
  EXPECT_NE(first.find("times, from 3.0"), std::string::npos) << "counted, with the first and last time: " << first;
  EXPECT_NE(first.find("in contact then: r1 and m0, m0 and world.obstacles[0]"), std::string::npos)
      << "the robot presses the mote on the wall by then: " << first;
  std::ifstream log(dir + "/log.csv");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text.find("LCP"), std::string::npos) << "log.csv, which the fingerprint covers, holds no warning";
  RunInto(dir + "-quiet", -1, &quiet_fingerprint);
  EXPECT_EQ(fingerprint, quiet_fingerprint) << "a warning does not change the run";
}

TEST(RunWarnings, AMotePushedAwayIsListed) {
  std::string fingerprint;
  const nlohmann::json summary = RunInto(::testing::TempDir() + "/warnings-mote", -1, &fingerprint);
  ASSERT_EQ(summary["motes_moved"].size(), 1u);
  EXPECT_EQ(summary["motes_moved"][0]["node"], "m0");
  EXPECT_GT(summary["motes_moved"][0]["moved_m"].get<double>(), 0.3) << "the robot shoved it towards the wall";
  ASSERT_EQ(summary["warnings"].size(), 1u);
  EXPECT_NE(summary["warnings"][0].get<std::string>().find("1 mote was pushed more than 0.25 m"), std::string::npos);
}

}  // namespace
}  // namespace sanet
