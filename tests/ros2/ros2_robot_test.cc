// `sanet agent --ros2`'s view of a ROS 2 robot: its topics' names (defaults, file, remapping),
// its messages as a Node's readings, and the robot over DDS (a participant in this process plays
// the robot: publishes odometry, a scan, ranges, a pose and /clock; reads cmd_vel).
#include "ros2_agent/ros2_robot.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include "robots/node_model.h"
#include "ros2_agent/readings.h"
#include "ros2_agent/robot_topics.h"
#include "ros2_presentation/robot_messages.h"
#include "ros2msg/codec.h"
#include "scenario/yaml_reader.h"
#include "sensors/ir/ir_ros2.h"
#include "sensors/laser/laser_ros2.h"
#include "sensors/range_fan.h"

namespace sanet::ros2_agent {
namespace {

std::string FileWith(const std::string& text) {
  const std::string path = std::filesystem::temp_directory_path() / ("robot_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(path) << text;
  return path;
}

TEST(RobotTopics, DefaultsAreTheFacesAndRemappingRenames) {
  RobotTopics t = DefaultTopics("scout", 2);
  EXPECT_EQ(FullName(t, t.odom), "/scout/odom");
  EXPECT_EQ(FullName(t, t.ir[1]), "/scout/ir_1");
  EXPECT_EQ(FullName(t, t.clock), "/clock");
  Remap("odom=/tb4/odom", t);
  Remap("ir_1=sonar/right", t);
  Remap("ground_truth=none", t);
  EXPECT_EQ(FullName(t, t.odom), "/tb4/odom");
  EXPECT_EQ(FullName(t, t.ir[1]), "/scout/sonar/right");
  EXPECT_EQ(t.ground_truth_type, GroundTruthType::kNone);
  EXPECT_THROW(Remap("odometry=/x", t), std::invalid_argument);
  EXPECT_THROW(Remap("ir_2=/x", t), std::invalid_argument);
  EXPECT_THROW(Remap("odom=/bad name", t), std::invalid_argument);
  EXPECT_THROW(Remap("odom", t), std::invalid_argument);
}

TEST(RobotTopics, AFileRetypesAndItsMistakesNameTheLine) {
  RobotTopics t = DefaultTopics("r1", 0);
  ReadRobotFile(FileWith("namespace: tb4_1\n"
                         "odom: {topic: odom, qos: reliable}\n"
                         "ground_truth: {topic: /mocap/tb4_1/pose, type: pose_stamped}\n"
                         "cmd_vel: {topic: cmd_vel, type: twist_stamped}\n"
                         "use_sim_time: true\n"),
                t);
  EXPECT_EQ(FullName(t, t.odom), "/tb4_1/odom");
  EXPECT_EQ(t.odom.qos, Qos::kDefault);
  EXPECT_EQ(t.ground_truth_type, GroundTruthType::kPoseStamped);
  EXPECT_EQ(t.cmd_vel_type, CmdVelType::kTwistStamped);
  EXPECT_TRUE(t.use_sim_time);
  try {
    ReadRobotFile(FileWith("odom: odom\ncmd_vel: {topic: cmd_vel, type: twisty}\n"), t);
    FAIL() << "a bad type is refused";
  } catch (const scenario::ScenarioError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.field(), "cmd_vel.type");
  }
  EXPECT_THROW(ReadRobotFile(FileWith("ir: [a, b]\n"), t), scenario::ScenarioError);  // r1 has no IR here
  EXPECT_THROW(ReadRobotFile(FileWith("odometry: odom\n"), t), scenario::ScenarioError);
}

TEST(Readings, OdometryIsInTheWorldFromTheStartPoseAndScansSayNothingSeenAsMaxRange) {
  const Pose2D p = InWorld({1, 2, M_PI / 2}, {1, 0, 0.5});
  EXPECT_NEAR(p.x, 1, 1e-12);
  EXPECT_NEAR(p.y, 3, 1e-12);
  EXPECT_NEAR(p.theta, M_PI / 2 + 0.5, 1e-12);
  msg::geometry_msgs::Pose pose;
  pose.orientation.z = std::sin(-1.0);
  pose.orientation.w = std::cos(-1.0);
  EXPECT_NEAR(PoseOf(pose).theta, -2.0, 1e-12);
  msg::sensor_msgs::LaserScan scan;
  scan.angle_min = -1;
  scan.angle_increment = 0.5f;
  scan.range_max = 4;
  scan.ranges = {1.5f, INFINITY, NAN, 9.0f, -1.0f};
  const RangeScan s = ScanOf(scan);
  EXPECT_EQ(s.ranges, (std::vector<double>{1.5, 4, 4, 4, 0}));
  EXPECT_DOUBLE_EQ(s.angles[4], 1.0);
  EXPECT_DOUBLE_EQ(Seconds(StampAt(12.25)), 12.25);
}

// REP 117 both ways: the face (and the MCAP log) says "nothing seen" as +Inf, and the agent reads
// +Inf back as the sensor's maximum, which is what the controller got in the simulation.
TEST(Readings, NothingSeenIsInfinityOnTheWireAndTheMaximumInTheController) {
  RangeScan laser;
  laser.max_range = 8;
  laser.angles = {-0.5, 0, 0.5};
  laser.ranges = {2.5, 8, 7.999};
  const msg::sensor_msgs::LaserScan sent = ros2_presentation::ScanOf(laser, 1.0, "r/laser");
  EXPECT_EQ(sent.ranges[0], 2.5f);
  EXPECT_TRUE(std::isinf(sent.ranges[1]) && sent.ranges[1] > 0) << "a beam that hit nothing";
  EXPECT_EQ(sent.ranges[2], 7.999f);
  EXPECT_EQ(sent.range_max, 8.0f);
  EXPECT_EQ(ScanOf(sent).ranges, (std::vector<double>{2.5, 8, static_cast<float>(7.999)}));
  RangeScan ir;
  ir.max_range = 0.8;
  ir.angles = {0, 1};
  ir.ranges = {0.8, 0.3};
  EXPECT_TRUE(std::isinf(ros2_presentation::RangeOf(ir, 0, 1.0, "r/ir_0", 0).range));
  EXPECT_EQ(ros2_presentation::RangeOf(ir, 1, 1.0, "r/ir_1", 0).range, 0.3f);
}

// Publishes as a robot would, and reads what the agent's side writes.
class PlayedRobot {
 public:
  explicit PlayedRobot(std::uint32_t domain) : dds_(domain) {}
  template <typename Message>
  void Publish(const std::string& topic, const Message& m, Qos qos = Qos::kSensorData) {
    auto& writer = writers_[topic];
    if (!writer) writer = dds_.Writer(topic, ros2msg::TypeOf<Message>::kDdsName, qos);
    dds_.Write(writer, ros2msg::Encode(m));
  }
  template <typename Message>
  std::vector<Message> Take(const std::string& topic) {
    auto& reader = readers_[topic];
    if (!reader) reader = dds_.Reader(topic, ros2msg::TypeOf<Message>::kDdsName, Qos::kDefault);
    std::vector<Message> got;
    for (const auto& s : dds_.Take(reader))
      if (auto m = ros2msg::Decode<Message>(s.bytes)) got.push_back(*m);
    return got;
  }

 private:
  ros2_face::DdsDomain dds_;
  std::map<std::string, ros2_face::DdsDomain::Entity> writers_, readers_;
};

// Repeats `step` until `done` (DDS discovery takes a moment), for up to 10 s.
bool Eventually(const std::function<void()>& step, const std::function<bool()>& done) {
  for (int i = 0; i < 1000; ++i) {
    step();
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

std::uint32_t TestDomain() { return 150 + static_cast<std::uint32_t>(::getpid() % 30); }  // and +30: below 233

TEST(Ros2Robot, ReadsTheRobotsTopicsAndDrivesItsCmdVel) {
  Ros2RobotSettings settings;
  settings.domain = TestDomain();
  settings.model = sensors::DefaultModel(robots::ModelKind::kOmni3);
  settings.topics = DefaultTopics("r1", sensors::DefaultFan(settings.model, "ir")->angles.size());
  settings.topics.use_sim_time = true;
  settings.start = {2, 0, M_PI};
  Ros2Robot robot(settings);
  PlayedRobot played(settings.domain);
  msg::nav_msgs::Odometry odom;
  odom.pose.pose.position.x = 1;
  msg::sensor_msgs::Range range;
  range.max_range = 0.8f;
  range.range = 0.3f;
  msg::rosgraph_msgs::Clock clock;
  clock.clock = StampAt(7.5);
  const auto publish = [&] {
    played.Publish("/r1/odom", odom, Qos::kDefault);
    for (std::size_t i = 0; i < settings.topics.ir.size(); ++i) played.Publish("/r1/ir_" + std::to_string(i), range);
    played.Publish("/r1/ground_truth", odom);
    played.Publish("/clock", clock, Qos::kClock);
    robot.Poll(1.0);
  };
  ASSERT_TRUE(
      Eventually(publish, [&] { return robot.Odometry() && robot.Ir() && robot.GroundTruth() && robot.SimTime(); }));
  EXPECT_NEAR(robot.Odometry()->x, 1, 1e-9) << "1 m ahead of a start at x = 2 facing -x";
  EXPECT_NEAR(robot.GroundTruth()->x, 1, 1e-9) << "ground truth is in the world as it comes";
  EXPECT_NEAR(robot.Ir()->ranges[3], 0.3, 1e-6);
  EXPECT_EQ(robot.Ir()->angles, sensors::DefaultFan(settings.model, "ir")->angles);
  EXPECT_DOUBLE_EQ(*robot.SimTime(), 7.5);
  EXPECT_EQ(*robot.OdometryAt(), 1.0);
  std::vector<msg::geometry_msgs::Twist> heard;
  ASSERT_TRUE(Eventually(
      [&] {
        robot.Drive({0.25, -0.1, 0.5}, 7.5);
        for (const auto& t : played.Take<msg::geometry_msgs::Twist>("/r1/cmd_vel")) heard.push_back(t);
      },
      [&] { return !heard.empty(); }));
  EXPECT_DOUBLE_EQ(heard.back().linear.x, 0.25);
  EXPECT_DOUBLE_EQ(heard.back().linear.y, -0.1);
  EXPECT_DOUBLE_EQ(heard.back().angular.z, 0.5);
}

TEST(Ros2Robot, TwistStampedAndAPoseStampedGroundTruthAndBadSamplesCounted) {
  Ros2RobotSettings settings;
  settings.domain = TestDomain() + 30;
  settings.model = sensors::DefaultModel(robots::ModelKind::kDiffDrive);
  settings.topics = DefaultTopics("r2", 0);
  Remap("ground_truth=/mocap/r2", settings.topics);
  settings.topics.ground_truth_type = GroundTruthType::kPoseStamped;
  settings.topics.cmd_vel_type = CmdVelType::kTwistStamped;
  Ros2Robot robot(settings);
  PlayedRobot played(settings.domain);
  msg::geometry_msgs::PoseStamped mocap;
  mocap.pose.position.y = -3;
  ros2_face::DdsDomain liar(settings.domain);  // on the scan topic, typed as a scan: bytes that are none
  const auto bad = liar.Writer("/r2/scan", ros2msg::TypeOf<msg::sensor_msgs::LaserScan>::kDdsName, Qos::kSensorData);
  ASSERT_TRUE(Eventually(
      [&] {
        played.Publish("/mocap/r2", mocap);
        liar.Write(bad, ros2msg::Bytes{0, 1, 0, 0, 1});
        robot.Poll(0);
      },
      [&] { return robot.GroundTruth() && robot.counts().undecodable > 0; }));
  EXPECT_NEAR(robot.GroundTruth()->y, -3, 1e-12);
  EXPECT_FALSE(robot.Laser());
  std::vector<msg::geometry_msgs::TwistStamped> heard;
  ASSERT_TRUE(Eventually(
      [&] {
        robot.Drive({0.3, 0, 0}, 12.5);
        for (const auto& t : played.Take<msg::geometry_msgs::TwistStamped>("/r2/cmd_vel")) heard.push_back(t);
      },
      [&] { return !heard.empty(); }));
  EXPECT_DOUBLE_EQ(heard.back().twist.linear.x, 0.3);
  EXPECT_DOUBLE_EQ(Seconds(heard.back().header.stamp), 12.5);
  EXPECT_EQ(heard.back().header.frame_id, "r2/base_link");
}

}  // namespace
}  // namespace sanet::ros2_agent
