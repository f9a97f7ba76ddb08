// Odometry as nav_msgs/Odometry on /<robot>/odom (or /<robot>/<instance>): the pose in <robot>/odom,
// relative to the start pose, with the body's velocity in <robot>/base_link.
#include "ros2_presentation/sensor_messages.h"

namespace sanet::ros2_presentation {
namespace {

class OdometryMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& instance, const std::any& /*settings*/) const override {
    SensorTopic topic = TopicFor<msg::nav_msgs::Odometry>(TopicName(instance, "odometry", "odom"));
    topic.reliable = true;  // as ROS 2 drivers publish odometry
    return {topic};
  }
  std::vector<SensorMessage> Messages(const std::string& /*instance*/, const std::any& /*settings*/,
                                      const SensorReading& reading, const MessageContext& context) const override {
    const Pose2D pose = Relative(context.start, std::get<Pose2D>(reading));
    return {MessageOn(0, OdometryIn(context.frames->odom, context.frames->base, context.time, pose,
                                    InBody(context.velocity, context.truth.theta)))};
  }
};

}  // namespace

const SensorMessages& OdometrySensorMessages() {
  static const OdometryMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
