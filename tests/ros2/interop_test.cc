// sanet's ROS 2 encoders against Cyclone DDS's own, byte for byte: for every type the face
// uses, a sample written by Cyclone with types idlc generated from IDL written from ROS 2's
// definitions (tests/ros2/ros2_types.idl, independent of sanet's .msg copies) arrives through a
// sanet raw-CDR reader as exactly the bytes sanet's encoder makes of the same values; and what
// sanet writes, Cyclone's typed reader decodes to those values. In one process, over DDS.
#include <dds/dds.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <string>
#include <thread>

#include "ros2_face/raw_cdr_type.h"
#include "ros2_types.h"
#include "ros2msg/codec.h"

namespace sanet::ros2msg {
namespace {

class Ros2Interop : public ::testing::Test {
 protected:
  void SetUp() override { participant_ = dds_create_participant(200 + getpid() % 30, nullptr, nullptr); }
  void TearDown() override { dds_delete(participant_); }

  dds_entity_t Endpoints(const dds_topic_descriptor_t* desc, const std::string& name, dds_entity_t* typed_writer,
                         dds_entity_t* typed_reader, dds_entity_t* raw_reader, dds_entity_t* raw_writer) {
    dds_qos_t* q = dds_create_qos();
    dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_history(q, DDS_HISTORY_KEEP_ALL, 0);
    const dds_entity_t typed = dds_create_topic(participant_, desc, name.c_str(), nullptr, nullptr);
    ddsi_sertype* type = ros2_face::MakeRawCdrType(desc->m_typename);
    const dds_entity_t raw = dds_create_topic_sertype(participant_, name.c_str(), &type, nullptr, nullptr, nullptr);
    *raw_reader = dds_create_reader(participant_, raw, q, nullptr);
    *typed_reader = dds_create_reader(participant_, typed, q, nullptr);
    *typed_writer = dds_create_writer(participant_, typed, q, nullptr);
    *raw_writer = dds_create_writer(participant_, raw, q, nullptr);
    dds_delete_qos(q);
    return typed;
  }

  // Cyclone writes `sample`; sanet's reader takes it as bytes.
  Bytes CycloneBytes(const dds_topic_descriptor_t* desc, const std::string& name, const void* sample) {
    Endpoints(desc, "rt/sanet_interop/" + name, &typed_writer_, &typed_reader_, &raw_reader_, &raw_writer_);
    EXPECT_EQ(dds_write(typed_writer_, sample), DDS_RETCODE_OK);
    Bytes bytes;
    void* buffer = &bytes;
    dds_sample_info_t info;
    for (int i = 0; i < 200 && dds_take(raw_reader_, &buffer, &info, 1, 1) <= 0; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return bytes;
  }

  // sanet writes `bytes`; Cyclone's typed reader takes the sample (loaned: return it after).
  void* CycloneSample(const Bytes& bytes) {
    EXPECT_EQ(dds_write(raw_writer_, &bytes), DDS_RETCODE_OK);
    dds_sample_info_t info;
    for (int i = 0; i < 200; ++i) {
      loan_[0] = nullptr;
      while (dds_take(typed_reader_, loan_, &info, 1, 1) > 0)
        if (info.valid_data) return loan_[0];
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return nullptr;
  }

  dds_entity_t participant_ = 0, typed_writer_ = 0, typed_reader_ = 0, raw_reader_ = 0, raw_writer_ = 0;
  void* loan_[1] = {nullptr};
};

TEST_F(Ros2Interop, OdometryIsTheSameBytesBothWays) {
  nav_msgs_msg_dds__Odometry_ c;
  std::memset(&c, 0, sizeof c);
  c.header.stamp.sec = 12;
  c.header.stamp.nanosec = 345;
  c.header.frame_id = const_cast<char*>("r1/odom");
  c.child_frame_id = const_cast<char*>("r1/base_link");
  c.pose.pose.position.x = 1.25;
  c.pose.pose.orientation.z = std::sin(0.2);
  c.pose.pose.orientation.w = std::cos(0.2);
  c.pose.covariance[7] = 0.5;
  c.twist.twist.linear.x = 0.3;
  c.twist.twist.angular.z = -0.1;
  nav_msgs::Odometry m;
  m.header.stamp.sec = 12;
  m.header.stamp.nanosec = 345;
  m.header.frame_id = "r1/odom";
  m.child_frame_id = "r1/base_link";
  m.pose.pose.position.x = 1.25;
  m.pose.pose.orientation.z = std::sin(0.2);
  m.pose.pose.orientation.w = std::cos(0.2);
  m.pose.covariance[7] = 0.5;
  m.twist.twist.linear.x = 0.3;
  m.twist.twist.angular.z = -0.1;
  EXPECT_EQ(CycloneBytes(&nav_msgs_msg_dds__Odometry__desc, "odom", &c), Encode(m));
  auto* back = static_cast<nav_msgs_msg_dds__Odometry_*>(CycloneSample(Encode(m)));
  ASSERT_TRUE(back);
  EXPECT_STREQ(back->child_frame_id, "r1/base_link");
  EXPECT_EQ(back->pose.covariance[7], 0.5);
  EXPECT_EQ(back->twist.twist.angular.z, -0.1);
  dds_return_loan(typed_reader_, loan_, 1);
}

TEST_F(Ros2Interop, LaserScanIsTheSameBytesBothWays) {
  float ranges[] = {1.5f, 2.0f, INFINITY};
  sensor_msgs_msg_dds__LaserScan_ c;
  std::memset(&c, 0, sizeof c);
  c.header.frame_id = const_cast<char*>("r1/laser");
  c.angle_min = -1.5f;
  c.angle_max = 1.5f;
  c.angle_increment = 1.5f;
  c.range_max = 8;
  c.ranges._buffer = ranges;
  c.ranges._length = c.ranges._maximum = 3;
  sensor_msgs::LaserScan m;
  m.header.frame_id = "r1/laser";
  m.angle_min = -1.5f;
  m.angle_max = 1.5f;
  m.angle_increment = 1.5f;
  m.range_max = 8;
  m.ranges = {1.5f, 2.0f, INFINITY};
  EXPECT_EQ(CycloneBytes(&sensor_msgs_msg_dds__LaserScan__desc, "scan", &c), Encode(m));
  auto* back = static_cast<sensor_msgs_msg_dds__LaserScan_*>(CycloneSample(Encode(m)));
  ASSERT_TRUE(back);
  ASSERT_EQ(back->ranges._length, 3u);
  EXPECT_EQ(back->ranges._buffer[1], 2.0f);
  EXPECT_EQ(back->intensities._length, 0u);
  dds_return_loan(typed_reader_, loan_, 1);
}

TEST_F(Ros2Interop, RangeIsTheSameBytesBothWays) {
  sensor_msgs_msg_dds__Range_ c;
  std::memset(&c, 0, sizeof c);
  c.header.frame_id = const_cast<char*>("r2/ir_3");
  c.radiation_type = 1;
  c.max_range = 0.8f;
  c.range = 0.42f;
  c.variance = 0.0004f;
  sensor_msgs::Range m;
  m.header.frame_id = "r2/ir_3";
  m.radiation_type = sensor_msgs::Range::INFRARED;
  m.max_range = 0.8f;
  m.range = 0.42f;
  m.variance = 0.0004f;
  EXPECT_EQ(CycloneBytes(&sensor_msgs_msg_dds__Range__desc, "range", &c), Encode(m));
  auto* back = static_cast<sensor_msgs_msg_dds__Range_*>(CycloneSample(Encode(m)));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->radiation_type, 1);
  EXPECT_EQ(back->range, 0.42f);
  dds_return_loan(typed_reader_, loan_, 1);
}

TEST_F(Ros2Interop, ImuIsTheSameBytesBothWays) {
  sensor_msgs_msg_dds__Imu_ c;
  std::memset(&c, 0, sizeof c);
  c.header.stamp.sec = 12, c.header.stamp.nanosec = 5000000;
  c.header.frame_id = const_cast<char*>("little/imu");
  c.orientation.w = 1;  // geometry_msgs/Quaternion's default: the identity
  c.orientation_covariance[0] = -1;
  c.angular_velocity.z = 0.75, c.angular_velocity_covariance[8] = 2.5e-5;
  c.linear_acceleration.x = 0.125, c.linear_acceleration.z = 9.81, c.linear_acceleration_covariance[4] = 4e-4;
  sensor_msgs::Imu m;
  m.header.stamp.sec = 12, m.header.stamp.nanosec = 5000000;
  m.header.frame_id = "little/imu";
  m.orientation_covariance[0] = -1;
  m.angular_velocity.z = 0.75, m.angular_velocity_covariance[8] = 2.5e-5;
  m.linear_acceleration.x = 0.125, m.linear_acceleration.z = 9.81, m.linear_acceleration_covariance[4] = 4e-4;
  EXPECT_EQ(CycloneBytes(&sensor_msgs_msg_dds__Imu__desc, "imu", &c), Encode(m));
  auto* back = static_cast<sensor_msgs_msg_dds__Imu_*>(CycloneSample(Encode(m)));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->linear_acceleration.z, 9.81);
  EXPECT_EQ(back->orientation_covariance[0], -1);
  dds_return_loan(typed_reader_, loan_, 1);
}

TEST_F(Ros2Interop, NavSatFixIsTheSameBytesBothWays) {
  sensor_msgs_msg_dds__NavSatFix_ c;
  std::memset(&c, 0, sizeof c);
  c.header.frame_id = const_cast<char*>("little/gnss");
  c.status.status = -1, c.status.service = 1;
  c.latitude = 52.2053, c.longitude = -0.1218, c.altitude = std::nan("");
  c.position_covariance[0] = c.position_covariance[4] = 1.44, c.position_covariance[8] = 6.25;
  c.position_covariance_type = 2;
  sensor_msgs::NavSatFix m;
  m.header.frame_id = "little/gnss";
  m.status.status = -1, m.status.service = 1;
  m.latitude = 52.2053, m.longitude = -0.1218, m.altitude = std::nan("");
  m.position_covariance[0] = m.position_covariance[4] = 1.44, m.position_covariance[8] = 6.25;
  m.position_covariance_type = 2;
  EXPECT_EQ(CycloneBytes(&sensor_msgs_msg_dds__NavSatFix__desc, "fix", &c), Encode(m));
  auto* back = static_cast<sensor_msgs_msg_dds__NavSatFix_*>(CycloneSample(Encode(m)));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->status.status, -1);
  EXPECT_EQ(back->status.service, 1);
  EXPECT_EQ(back->longitude, -0.1218);
  EXPECT_TRUE(std::isnan(back->altitude));
  EXPECT_EQ(back->position_covariance_type, 2);
  dds_return_loan(typed_reader_, loan_, 1);
}

TEST_F(Ros2Interop, JointStateIsTheSameBytesBothWays) {
  char left[] = "left_wheel_joint", right[] = "right_wheel_joint";
  char* names[] = {left, right};
  double position[] = {12.5, -3.25}, velocity[] = {4, -4};
  sensor_msgs_msg_dds__JointState_ c;
  std::memset(&c, 0, sizeof c);
  c.header.frame_id = const_cast<char*>("little/base_link");
  c.name._length = c.name._maximum = 2, c.name._buffer = names;
  c.position._length = c.position._maximum = 2, c.position._buffer = position;
  c.velocity._length = c.velocity._maximum = 2, c.velocity._buffer = velocity;
  sensor_msgs::JointState m;
  m.header.frame_id = "little/base_link";
  m.name = {left, right};
  m.position = {12.5, -3.25};
  m.velocity = {4, -4};
  EXPECT_EQ(CycloneBytes(&sensor_msgs_msg_dds__JointState__desc, "joints", &c), Encode(m));
  auto* back = static_cast<sensor_msgs_msg_dds__JointState_*>(CycloneSample(Encode(m)));
  ASSERT_TRUE(back);
  ASSERT_EQ(back->name._length, 2u);
  EXPECT_STREQ(back->name._buffer[1], "right_wheel_joint");
  EXPECT_EQ(back->velocity._buffer[1], -4);
  EXPECT_EQ(back->effort._length, 0u);
  dds_return_loan(typed_reader_, loan_, 1);
}

TEST_F(Ros2Interop, TfMessageIsTheSameBytesBothWays) {
  geometry_msgs_msg_dds__TransformStamped_ transforms[2];
  std::memset(transforms, 0, sizeof transforms);
  tf2_msgs::TFMessage m;
  m.transforms.resize(2);
  const char* children[] = {"r1/odom", "r2/odom"};
  for (int i = 0; i < 2; ++i) {
    transforms[i].header.frame_id = const_cast<char*>("world");
    transforms[i].child_frame_id = const_cast<char*>(children[i]);
    transforms[i].transform.translation.y = 4.0 * i;
    transforms[i].transform.rotation.w = 1;
    m.transforms[i].header.frame_id = "world";
    m.transforms[i].child_frame_id = children[i];
    m.transforms[i].transform.translation.y = 4.0 * i;
    m.transforms[i].transform.rotation.w = 1;
  }
  tf2_msgs_msg_dds__TFMessage_ c;
  c.transforms._buffer = transforms;
  c.transforms._length = c.transforms._maximum = 2;
  c.transforms._release = false;
  EXPECT_EQ(CycloneBytes(&tf2_msgs_msg_dds__TFMessage__desc, "tf", &c), Encode(m));
  auto* back = static_cast<tf2_msgs_msg_dds__TFMessage_*>(CycloneSample(Encode(m)));
  ASSERT_TRUE(back);
  ASSERT_EQ(back->transforms._length, 2u);
  EXPECT_STREQ(back->transforms._buffer[1].child_frame_id, "r2/odom");
  EXPECT_EQ(back->transforms._buffer[1].transform.translation.y, 4.0);
  dds_return_loan(typed_reader_, loan_, 1);
}

TEST_F(Ros2Interop, ClockTwistAndTwistStampedAreTheSameBytesBothWays) {
  rosgraph_msgs_msg_dds__Clock_ clock{{42, 5000000}};
  rosgraph_msgs::Clock m_clock;
  m_clock.clock.sec = 42;
  m_clock.clock.nanosec = 5000000;
  EXPECT_EQ(CycloneBytes(&rosgraph_msgs_msg_dds__Clock__desc, "clock", &clock), Encode(m_clock));

  geometry_msgs_msg_dds__Twist_ twist;
  std::memset(&twist, 0, sizeof twist);
  twist.linear.x = 0.3;
  twist.angular.z = 0.5;
  geometry_msgs::Twist m_twist;
  m_twist.linear.x = 0.3;
  m_twist.angular.z = 0.5;
  EXPECT_EQ(CycloneBytes(&geometry_msgs_msg_dds__Twist__desc, "twist", &twist), Encode(m_twist));

  geometry_msgs_msg_dds__TwistStamped_ stamped;
  std::memset(&stamped, 0, sizeof stamped);
  stamped.header.frame_id = const_cast<char*>("r1/base_link");
  stamped.twist.linear.y = -0.2;
  geometry_msgs::TwistStamped m_stamped;
  m_stamped.header.frame_id = "r1/base_link";
  m_stamped.twist.linear.y = -0.2;
  EXPECT_EQ(CycloneBytes(&geometry_msgs_msg_dds__TwistStamped__desc, "twist_stamped", &stamped), Encode(m_stamped));
  auto* back = static_cast<geometry_msgs_msg_dds__TwistStamped_*>(CycloneSample(Encode(m_stamped)));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->twist.linear.y, -0.2);
  dds_return_loan(typed_reader_, loan_, 1);
}

}  // namespace
}  // namespace sanet::ros2msg
