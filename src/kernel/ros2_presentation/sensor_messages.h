// A sensor kind's ROS 2 presentation: the topics an instance publishes on (under its robot's
// namespace), the messages of one reading, and where the instance is mounted on the body (static
// transforms). The run's log (ros2_presentation/run_messages.h) and the ROS 2 face publish through it alike.
// Each kind's folder holds its part, sensors/<kind>/<kind>_ros2.cc, registered once
// (sensors/sensor_kinds.h).
//
// Names: a kind's own instance keeps its historic topic (/<robot>/scan for the laser); a named
// instance uses its name in place of the kind's (/<robot>/laser_rear), and so do its frames
// (<robot>/laser_rear).
#pragma once

#include <any>
#include <cstdint>
#include <string>
#include <vector>

#include "ros2_presentation/robot_messages.h"
#include "ros2msg/codec.h"
#include "sanet/readings.h"
#include "sensors/sensor_kinds.h"
#include "sensors/sensor_registry.h"

namespace sanet::ros2_presentation {

struct SensorTopic {
  std::string name;        // under the robot's namespace: "scan", "ir_0", "laser_rear"
  std::string type;        // "sensor_msgs/msg/LaserScan"
  std::string dds_type;    // "sensor_msgs::msg::dds_::LaserScan_"
  std::string definition;  // the ros2msg schema text
  bool reliable = false;   // QoS on DDS: best effort (ROS 2's sensor-data profile) unless reliable
  // Where the topic is: on the ROS 2 face, in the run's record (trace.mcap, the Foxglove stream),
  // or both (a camera's raw pictures go to the face, its compressed ones to the record).
  bool on_face = true, recorded = true;
};

// One message of a reading, on topic `topic` (an index into the instance's topics), CDR-encoded.
struct SensorMessage {
  std::size_t topic = 0;
  std::vector<std::uint8_t> cdr;
};

// What the messages of a reading may refer to besides it.
struct MessageContext {
  double time = 0;                      // s, simulated: the messages' stamp
  const RobotFrames* frames = nullptr;  // the robot's frames (odom, base_link, its prefix)
  Pose2D start;                         // the robot's start pose (the origin of its odom frame)
  Pose2D truth;                         // where the body is now
  Twist2D velocity;                     // the body's velocity, world frame
  bool recording = false;               // for the run's record (trace.mcap, the Foxglove stream), not the face
};

class SensorMessages {
 public:
  virtual ~SensorMessages() = default;
  virtual std::vector<SensorTopic> Topics(const std::string& instance, const std::any& settings) const = 0;
  virtual std::vector<SensorMessage> Messages(const std::string& instance, const std::any& settings,
                                              const SensorReading& reading, const MessageContext& context) const = 0;
  // base_link -> the instance's frames, stamped `t`; none for a sensor without a place.
  virtual void Mounts(const std::string& /*instance*/, const std::any& /*settings*/, const RobotFrames& /*frames*/,
                      double /*t*/, std::vector<msg::geometry_msgs::TransformStamped>& /*out*/) const {}
};

#define SANET_DECLARE_SENSOR_MESSAGES(name, Name) const SensorMessages& Name##SensorMessages();
SANET_SENSOR_KINDS(SANET_DECLARE_SENSOR_MESSAGES)
#undef SANET_DECLARE_SENSOR_MESSAGES

// The part of kind `kind`; null for a kind without one.
const SensorMessages* MessagesOf(const std::string& kind);

// The topic of message type M named `name`.
template <typename M>
SensorTopic TopicFor(std::string name) {
  return {std::move(name), ros2msg::TypeOf<M>::kName, ros2msg::TypeOf<M>::kDdsName, ros2msg::TypeOf<M>::Definition()};
}
template <typename M>
SensorTopic FaceTopicFor(std::string name) {
  SensorTopic topic = TopicFor<M>(std::move(name));
  topic.recorded = false;
  return topic;
}
template <typename M>
SensorTopic RecordTopicFor(std::string name) {
  SensorTopic topic = TopicFor<M>(std::move(name));
  topic.on_face = false;
  return topic;
}
template <typename M>
SensorMessage MessageOn(std::size_t topic, const M& message) {
  return {topic, ros2msg::Encode(message)};
}
// `kind_name` ("scan") for the kind's own instance, the instance's name otherwise.
inline std::string TopicName(const std::string& instance, const std::string& kind, const std::string& kind_name) {
  return instance == kind ? kind_name : instance;
}

}  // namespace sanet::ros2_presentation
