// The encoders as sensor_msgs/JointState on /<robot>/joint_states (or /<robot>/<instance>), in
// <robot>/base_link: each wheel joint's name, position (rad) and velocity (rad/s), no effort.
#include "ros2_presentation/sensor_messages.h"

namespace sanet::ros2_presentation {
namespace {

using msg::sensor_msgs::JointState;

class EncodersMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& instance, const std::any& /*settings*/) const override {
    SensorTopic topic = TopicFor<JointState>(TopicName(instance, "encoders", "joint_states"));
    topic.reliable = true;  // as robot_state_publisher's input is published
    return {topic};
  }
  std::vector<SensorMessage> Messages(const std::string& /*instance*/, const std::any& /*settings*/,
                                      const SensorReading& reading, const MessageContext& context) const override {
    const auto& joints = std::get<JointStatesReading>(reading);
    JointState s;
    s.header.stamp = StampOf(context.time);
    s.header.frame_id = context.frames->base;
    s.name = joints.names;
    s.position = joints.angles;
    s.velocity = joints.speeds;
    return {MessageOn(0, s)};
  }
};

}  // namespace

const SensorMessages& EncodersSensorMessages() {
  static const EncodersMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
