// Where the run's ROS 2 messages go (ros2_presentation/run_messages.h): the MCAP log (ros2_presentation/mcap_sink.h), a
// live Foxglove stream (foxglove/), each told of a topic once, before its first message. Sinks are called on the
// simulation's thread and must not block it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sanet::ros2_presentation {

struct Topic {
  std::uint32_t id = 0;    // 1, 2, ... in the order the run first published them
  std::string name;        // "/f1/scan"
  std::string type;        // "sensor_msgs/msg/LaserScan"
  std::string definition;  // the ros2msg schema: the type's definition and those it uses
  // Its last message stands until the next (/tf_static, /world): a sink that joins late gets it.
  bool latched = false;
};

class MessageSink {
 public:
  virtual ~MessageSink() = default;
  virtual void Advertise(const Topic& topic) = 0;
  // `cdr`: the message as ROS 2 serializes it; `time_ns`: simulated time of its event.
  virtual void Publish(const Topic& topic, std::uint64_t time_ns, const std::vector<std::uint8_t>& cdr) = 0;
  // Whether it wants messages now (a stream with no client does not): when no sink does, the
  // messages are not even made, except the latched ones.
  virtual bool Active() const { return true; }
};

}  // namespace sanet::ros2_presentation
