// Robots from URDF: what urdfdom reads of scenarios/robots/little-diff.urdf against the values
// worked out by hand from the file, and each refusal with its file, element and line.
#include "robots/urdf_robot.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace sanet::robots {
namespace {

const std::string kFile = std::string(SANET_SOURCE_DIR) + "/scenarios/robots/little-diff.urdf";

std::string Text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

UrdfRobot LittleDiff() { return ReadUrdf(kFile, Text(kFile), {"left_wheel_joint", "right_wheel_joint"}); }

TEST(Urdf, TheWheelsMassesChassisAndMountsAreTheFilesValues) {
  const UrdfRobot r = LittleDiff();
  EXPECT_EQ(r.name, "little_diff");
  EXPECT_EQ(r.base_link, "base_link");
  ASSERT_EQ(r.wheels.size(), 2u);
  EXPECT_DOUBLE_EQ(r.wheels[0].radius, 0.05);  // the wheel link's collision cylinder
  EXPECT_DOUBLE_EQ(r.wheels[1].radius, 0.05);
  EXPECT_NEAR(WheelSpacing(r.wheels[0], r.wheels[1]), 0.29, 1e-12);  // the joints at y = +-0.145
  EXPECT_NEAR(r.wheels[0].pose.xyz[1], 0.145, 1e-12);
  EXPECT_DOUBLE_EQ(r.wheels[0].mass, 0.25);
  EXPECT_NEAR(r.chassis_mass, 2.0 + 0.05 + 0.1 + 0.15, 1e-12);  // base, caster, mast, laser
  ASSERT_EQ(r.chassis.size(), 1u);
  EXPECT_EQ(r.chassis[0].kind, UrdfShape::Kind::kBox);
  EXPECT_DOUBLE_EQ(r.chassis[0].box[0], 0.30);
  EXPECT_DOUBLE_EQ(r.chassis[0].box[2], 0.10);
  EXPECT_NEAR(r.chassis[0].pose.xyz[0], -0.05, 1e-12);
  const UrdfPose& laser = r.links.at("laser");  // mast at (0.05, 0, 0.09), laser 0.12 above it
  EXPECT_NEAR(laser.xyz[0], 0.05, 1e-12);
  EXPECT_NEAR(laser.xyz[2], 0.21, 1e-12);
  EXPECT_NEAR(r.links.at("caster").xyz[0], -0.17, 1e-12);
  EXPECT_EQ(r.text, Text(kFile));
}

// The file with `from` replaced by `to` must be refused at `line` with `words` in the message.
void ExpectRefused(const std::string& from, const std::string& to, int line, const std::string& words,
                   std::vector<std::string> wheels = {"left_wheel_joint", "right_wheel_joint"}) {
  std::string text = Text(kFile);
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  try {
    ReadUrdf("robot.urdf", text, wheels);
    FAIL() << "accepted: " << to;
  } catch (const UrdfError& e) {
    EXPECT_EQ(e.file(), "robot.urdf");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(Urdf, EachFaultIsRefusedWithItsElementAndLine) {
  ExpectRefused("<link name=\"mast\">", "<xacro:property name=\"h\" value=\"1\"/>\n  <link name=\"mast\">", 69,
                "is xacro");
  ExpectRefused("<origin xyz=\"0 0 0.12\"/>", "<origin xyz=\"0 0 ${h}\"/>", 90, "is xacro");
  ExpectRefused("<joint name=\"right_wheel_joint\" type=\"continuous\">",
                "<joint name=\"right_wheel_joint\" type=\"fixed\">", 47, "continuous joint");
  ExpectRefused("<joint name=\"right_wheel_joint\" type=\"continuous\">",
                "<joint name=\"right_wheel_joint\" type=\"revolute\">", 47, "does not specify limits");
  ExpectRefused("<geometry><cylinder radius=\"0.05\" length=\"0.03\"/></geometry>",
                "<geometry><box size=\"0.1 0.1 0.03\"/></geometry>", 22, "collision> cylinder");
  ExpectRefused("<geometry><box size=\"0.30 0.24 0.10\"/></geometry>\n    </collision>",
                "<geometry><mesh filename=\"chassis.stl\"/></geometry>\n    </collision>", 6, "mesh only");
  ExpectRefused("<child link=\"laser\"/>", "<child link=\"lidar\"/>", 87, "lidar");
  ExpectRefused("</robot>", "</rob>", 92, "the XML");
  ExpectRefused("<robot name=\"little_diff\">", "<robot name=\"little_diff\">", 0, "no joint of that name",
                {"left_wheel_joint", "front_wheel_joint"});
}

}  // namespace
}  // namespace sanet::robots
