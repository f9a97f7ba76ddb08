// Every reading type of sanet/readings.h crosses the isolated controller's socket pair whole: the
// call codec writes a SensorReading (its alternative and every field) and reads back the same.
#include <gtest/gtest.h>

#include "hosting/node_call_codec.h"

namespace sanet {
namespace {

using hosting::node_calls::Get;
using hosting::node_calls::Put;

std::optional<SensorReading> RoundTrip(const std::optional<SensorReading>& reading) {
  Writer w;
  Put(w, reading);
  Reader r(w.bytes());
  std::optional<SensorReading> back = Get<std::optional<SensorReading>>(r);
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.at_end());
  return back;
}

TEST(ReadingCodec, EveryReadingTypeComesBackWhole) {
  ImuReading imu;
  imu.angular_velocity = {0.1, -0.2, 0.3};
  imu.linear_acceleration = {0, 0, 9.81};
  imu.orientation = Quaternion{0, 0, 0.6, 0.8};
  imu.orientation_covariance[0] = -1;
  imu.linear_acceleration_covariance[8] = 0.04;
  ImageReading image{2, 1, "rgb8", {1, 2, 3, 4, 5, 6}, {1.5f, 2.25f}};
  const std::vector<SensorReading> all = {
      RangeScan{{-0.5, 0.5}, {1.25, 8}, 8},
      Pose2D{1, -2, 0.5},
      BearingsReading{{{3, {2.5, -0.25}}, {7, {9, 1}}}},
      BatteryReading{3600, 0.5, 3.7, true, 7200, 0.25},
      imu,
      FixReading{48.1, 11.5, 520, FixReading::kSbasFix, {1, 0, 0, 0, 1, 0, 0, 0, 4}},
      JointStatesReading{{"left", "right"}, {0.1, 0.2}, {3, -3}},
      image,
  };
  ASSERT_EQ(all.size(), std::variant_size_v<SensorReading>) << "every alternative is tried";
  for (const SensorReading& reading : all) {
    const auto back = RoundTrip(reading);
    ASSERT_TRUE(back);
    ASSERT_EQ(back->index(), reading.index());
    Writer a, b;  // the same bytes again: every field came back
    Put(a, reading);
    Put(b, *back);
    EXPECT_EQ(a.bytes(), b.bytes()) << "alternative " << reading.index();
  }
  EXPECT_EQ(std::get<ImageReading>(*RoundTrip(image)).encoding, "rgb8");
  EXPECT_DOUBLE_EQ(std::get<ImuReading>(*RoundTrip(imu)).orientation->z, 0.6);
  EXPECT_FALSE(RoundTrip(std::nullopt)) << "no such sensor";
}

TEST(ReadingCodec, AnAlternativeNoWriterWritesIsAMalformedPacket) {
  Writer w;
  w.Bool(true).U8(static_cast<std::uint8_t>(std::variant_size_v<SensorReading>));
  Reader r(w.bytes());
  Get<std::optional<SensorReading>>(r);
  EXPECT_FALSE(r.ok());
}

}  // namespace
}  // namespace sanet
