// Any bytes as a ROS 2 message from the network (what the ROS 2 face takes from DDS): the first
// byte chooses the type, the rest is decoded. The decoder refuses or decodes, never crashes or
// allocates for a count the bytes cannot hold; what it decodes encodes to bytes that decode to
// the same message (compared as their encoding).
#include <cstdint>
#include <cstdlib>

#include "ros2msg/codec.h"

namespace {

using namespace sanet::ros2msg;

template <typename Message>
void Check(const std::uint8_t* data, std::size_t size) {
  const auto decoded = Decode<Message>(data, size);
  if (!decoded) return;
  const Bytes once = Encode(*decoded);
  const auto again = Decode<Message>(once);
  if (!again || Encode(*again) != once) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t* body = data + 1;
  const std::size_t n = size - 1;
  switch (data[0] % 8) {
    case 0:
      Check<geometry_msgs::Twist>(body, n);
      break;
    case 1:
      Check<geometry_msgs::TwistStamped>(body, n);
      break;
    case 2:
      Check<nav_msgs::Odometry>(body, n);
      break;
    case 3:
      Check<sensor_msgs::LaserScan>(body, n);
      break;
    case 4:
      Check<sensor_msgs::Range>(body, n);
      break;
    case 5:
      Check<tf2_msgs::TFMessage>(body, n);
      break;
    case 6:
      Check<rosgraph_msgs::Clock>(body, n);
      break;
    default:
      Check<std_msgs::Header>(body, n);
      break;
  }
  return 0;
}
