// sanet's ROS 2 messages in CDR as ROS 2 puts them on DDS: the bytes of known messages laid
// out by hand from the CDR rules, round trips of every type the face uses, and decoders that
// refuse bad input naming the field (never reading past the end or allocating for a forged
// count). The byte-for-byte comparison with Cyclone DDS's own encoder is the ROS 2 face's test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "ros2msg/codec.h"

namespace sanet::ros2msg {
namespace {

Bytes Le32(std::uint32_t v) {
  return {std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), std::uint8_t(v >> 24)};
}

Bytes Cat(std::initializer_list<Bytes> parts) {
  Bytes all;
  for (const Bytes& p : parts) all.insert(all.end(), p.begin(), p.end());
  return all;
}

TEST(Cdr, ATimeIsTheHeaderThenTwoLittleEndianWords) {
  builtin_interfaces::Time t;
  t.sec = 7;
  t.nanosec = 500000000;
  EXPECT_EQ(Encode(t), Cat({{0, 1, 0, 0}, Le32(7), Le32(500000000)}));
}

TEST(Cdr, AHeaderStringCountsItsNulAndTheNextDoubleIsAlignedToEight) {
  geometry_msgs::TransformStamped m;
  m.header.stamp.sec = 1;
  m.header.frame_id = "world";  // 4 + 6 bytes after the stamp's 8: offset 18
  m.child_frame_id = "r1";      // aligned to 20: 4 + 3 bytes, to 27
  m.transform.translation.x = 1.5;
  const Bytes b = Encode(m);
  const Bytes expected_start = Cat({{0, 1, 0, 0},
                                    Le32(1),
                                    Le32(0),
                                    Le32(6),
                                    {'w', 'o', 'r', 'l', 'd', 0},
                                    {0, 0},
                                    Le32(3),
                                    {'r', '1', 0},
                                    {0, 0, 0, 0, 0}});
  ASSERT_GE(b.size(), expected_start.size() + 8);
  EXPECT_EQ(Bytes(b.begin(), b.begin() + expected_start.size()), expected_start);
  double x = 0;
  std::memcpy(&x, b.data() + expected_start.size(), 8);  // offset 32 after the header: 8-aligned
  EXPECT_EQ(x, 1.5);
  EXPECT_EQ(b.size(), 4 + 32 + 7 * 8u);  // translation and rotation, seven doubles
}

TEST(Cdr, EveryTypeOfTheFaceRoundTrips) {
  nav_msgs::Odometry odom;
  odom.header.frame_id = "r1/odom";
  odom.child_frame_id = "r1/base_link";
  odom.pose.pose.position.x = 2.25;
  odom.pose.pose.orientation.z = std::sin(0.3);
  odom.pose.pose.orientation.w = std::cos(0.3);
  odom.pose.covariance[35] = 0.01;
  odom.twist.twist.angular.z = -0.5;
  const auto back = Decode<nav_msgs::Odometry>(Encode(odom));
  ASSERT_TRUE(back);
  EXPECT_EQ(Encode(*back), Encode(odom));
  EXPECT_EQ(back->child_frame_id, "r1/base_link");
  EXPECT_EQ(back->pose.covariance[35], 0.01);

  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "r1/laser";
  scan.angle_min = -1.5f;
  scan.ranges = {1.0f, 2.5f, INFINITY};
  const auto scan_back = Decode<sensor_msgs::LaserScan>(Encode(scan));
  ASSERT_TRUE(scan_back);
  EXPECT_EQ(scan_back->ranges.size(), 3u);
  EXPECT_TRUE(std::isinf(scan_back->ranges[2]));
  EXPECT_TRUE(scan_back->intensities.empty());

  sensor_msgs::Range range;
  range.radiation_type = sensor_msgs::Range::INFRARED;
  range.range = 0.42f;
  EXPECT_EQ(Encode(*Decode<sensor_msgs::Range>(Encode(range))), Encode(range));

  tf2_msgs::TFMessage tf;
  tf.transforms.resize(2);
  tf.transforms[1].child_frame_id = "r2/base_link";
  const auto tf_back = Decode<tf2_msgs::TFMessage>(Encode(tf));
  ASSERT_TRUE(tf_back);
  EXPECT_EQ(tf_back->transforms[1].child_frame_id, "r2/base_link");

  rosgraph_msgs::Clock clock;
  clock.clock.sec = 12;
  EXPECT_EQ(Decode<rosgraph_msgs::Clock>(Encode(clock))->clock.sec, 12);

  geometry_msgs::TwistStamped twist;
  twist.twist.linear.x = 0.3;
  EXPECT_EQ(Decode<geometry_msgs::TwistStamped>(Encode(twist))->twist.linear.x, 0.3);
}

TEST(Cdr, ThePayloadIsPaddedToFourAndTheOptionsSayByHowMuch) {
  std_msgs::Header h;
  h.stamp.sec = 7;
  h.stamp.nanosec = 9;
  h.frame_id = "world";  // 8 + 4 + 6 = 18 bytes: two of padding
  EXPECT_EQ(Encode(h), Cat({{0, 1, 0, 2}, Le32(7), Le32(9), Le32(6), {'w', 'o', 'r', 'l', 'd', 0, 0, 0}}));
  EXPECT_EQ(Decode<std_msgs::Header>(Encode(h))->frame_id, "world");
}

TEST(Cdr, BigEndianMessagesDecodeToo) {
  const Bytes big = {0, 0, 0, 0, 0, 0, 0, 7, 0, 0, 0, 9};
  const auto t = Decode<builtin_interfaces::Time>(big);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->sec, 7);
  EXPECT_EQ(t->nanosec, 9u);
}

TEST(Cdr, BadInputIsRefusedNamingTheField) {
  std::string error;
  EXPECT_FALSE(Decode<builtin_interfaces::Time>(Bytes{0, 1, 0}, &error));
  EXPECT_NE(error.find("encapsulation"), std::string::npos) << error;
  EXPECT_FALSE(Decode<builtin_interfaces::Time>(Bytes{0, 7, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, &error));
  EXPECT_NE(error.find("not plain CDR"), std::string::npos) << error;
  EXPECT_FALSE(Decode<builtin_interfaces::Time>(Cat({{0, 1, 0, 0}, Le32(1)}), &error));
  EXPECT_EQ(error, "builtin_interfaces/Time.nanosec: needs 4 bytes, 0 left");

  sensor_msgs::LaserScan scan;
  scan.ranges = {1, 2};
  Bytes forged = Encode(scan);
  const std::size_t count_at = forged.size() - 4 - 8 - 4;  // ranges' count, before 8 bytes and intensities'
  forged[count_at + 3] = 0x7f;                             // two billion ranges
  EXPECT_FALSE(Decode<sensor_msgs::LaserScan>(forged, &error));
  EXPECT_NE(error.find("sensor_msgs/LaserScan.ranges: a sequence of"), std::string::npos) << error;

  tf2_msgs::TFMessage tf;
  Bytes many = Encode(tf);
  many[4 + 3] = 0x40;  // a billion transforms in no bytes
  EXPECT_FALSE(Decode<tf2_msgs::TFMessage>(many, &error));
  EXPECT_NE(error.find("tf2_msgs/TFMessage.transforms"), std::string::npos) << error;

  std_msgs::Header h;
  h.frame_id = "abc";
  Bytes no_nul = Encode(h);
  no_nul.back() = 'd';
  EXPECT_FALSE(Decode<std_msgs::Header>(no_nul, &error));
  EXPECT_EQ(error, "std_msgs/Header.frame_id: a string without its closing NUL");

  geometry_msgs::Twist twist;
  Bytes truncated = Encode(twist);
  truncated.resize(truncated.size() - 1);
  EXPECT_FALSE(Decode<geometry_msgs::Twist>(truncated, &error));
  EXPECT_EQ(error, "geometry_msgs/Vector3.z: needs 8 bytes, 7 left");
}

TEST(Cdr, SchemaTextIsTheDefinitionThenEachTypeItUsesOnce) {
  const std::string odom = TypeOf<nav_msgs::Odometry>::Definition();
  EXPECT_EQ(odom.rfind("std_msgs/Header header\nstring child_frame_id\n", 0), 0u) << odom;
  const std::string separator = std::string(80, '=') + "\n";
  for (const char* used : {"std_msgs/Header", "builtin_interfaces/Time", "geometry_msgs/PoseWithCovariance",
                           "geometry_msgs/Pose", "geometry_msgs/Point", "geometry_msgs/Quaternion",
                           "geometry_msgs/TwistWithCovariance", "geometry_msgs/Twist", "geometry_msgs/Vector3"}) {
    const std::string block = separator + "MSG: " + used + "\n";
    const auto at = odom.find(block);
    EXPECT_NE(at, std::string::npos) << used;
    EXPECT_EQ(odom.find(block, at + 1), std::string::npos) << used << " twice";
  }
  EXPECT_STREQ(TypeOf<nav_msgs::Odometry>::kName, "nav_msgs/msg/Odometry");
  EXPECT_STREQ(TypeOf<nav_msgs::Odometry>::kDdsName, "nav_msgs::msg::dds_::Odometry_");
}

}  // namespace
}  // namespace sanet::ros2msg
