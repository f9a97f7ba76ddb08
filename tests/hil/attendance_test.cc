// The run's verdict on the robots only clients can drive (robot_server/attendance.h).
#include "robot_server/attendance.h"

#include <gtest/gtest.h>

namespace sanet::robot_server {
namespace {

// Nodes 0 and 2 have controllers (agents' robots); node 1 is a mote.
Attendance ThreeNodes() { return Attendance({"r0", "", "r2"}); }

TEST(Attendance, ARobotNoClientDroveIsNamed) {
  Attendance a = ThreeNodes();
  a.Joined(0, 0.2);
  EXPECT_EQ(a.NeverDriven(), std::vector<std::string>{"r2"});
  a.Joined(2, 1.0);
  EXPECT_TRUE(a.NeverDriven().empty());
}

TEST(Attendance, NodesWithoutControllersAreNotCounted) {
  Attendance a = ThreeNodes();
  a.Joined(1, 0.1);  // a client drove the mote's node: nothing to judge
  a.Joined(0, 0.1);
  a.Joined(2, 0.1);
  EXPECT_TRUE(a.NeverDriven().empty());
  EXPECT_FALSE(a.Summary().contains(""));
  EXPECT_EQ(a.Summary().size(), 2u);
}

TEST(Attendance, ALateJoinIsAWarningWithItsTime) {
  Attendance a = ThreeNodes();
  a.Joined(0, Attendance::kLateAfter - 0.1);
  a.Joined(2, 12.5);
  const std::vector<std::string> warnings = a.Warnings(60);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "robot r2 joined late: first driven at 12.5 s (its controller did not run before)");
}

TEST(Attendance, ADropOutIsAWarningWithItsTimesAndWhetherItCameBack) {
  Attendance a = ThreeNodes();
  a.Joined(0, 0.1);
  a.Left(0, 20.0, "disconnected");
  a.Joined(0, 24.0);
  a.Joined(2, 0.1);
  a.Left(2, 30.0, "not reading for 2 s");
  const std::vector<std::string> warnings = a.Warnings(60);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "robot r0 dropped out at 20.0 s (its client: disconnected), driven again from 24.0 s");
  EXPECT_EQ(warnings[1], "robot r2 dropped out at 30.0 s (its client: not reading for 2 s), not driven again");
  const auto summary = a.Summary();
  EXPECT_EQ(summary["r0"]["driven"].size(), 2u);
  EXPECT_TRUE(summary["r0"]["driven"][1]["to_s"].is_null());
  EXPECT_EQ(summary["r2"]["driven"][0]["left_because"], "not reading for 2 s");
}

TEST(Attendance, LeavingAtTheEndIsNoDropOut) {
  Attendance a = ThreeNodes();
  a.Joined(0, 0.1);
  a.Joined(2, 0.1);
  a.Left(0, 60.0, "disconnected");  // the run ended: its client went with it
  EXPECT_TRUE(a.Warnings(60).empty());
}

TEST(Attendance, RobotsTheRos2FaceDroveAreExcused) {
  Attendance a = ThreeNodes();
  a.Joined(0, 0.1);
  a.Excuse({"r2"});
  EXPECT_TRUE(a.NeverDriven().empty());
  EXPECT_FALSE(a.Summary().contains("r2"));
}

}  // namespace
}  // namespace sanet::robot_server
