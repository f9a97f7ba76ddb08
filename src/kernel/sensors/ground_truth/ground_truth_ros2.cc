// Ground truth as nav_msgs/Odometry on /<robot>/ground_truth (or /<robot>/<instance>): the pose in
// world, with the body's velocity in <robot>/base_link.
#include "ros2_presentation/sensor_messages.h"

namespace sanet::ros2_presentation {
namespace {

class GroundTruthMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& instance, const std::any& /*settings*/) const override {
    return {TopicFor<msg::nav_msgs::Odometry>(TopicName(instance, "ground_truth", "ground_truth"))};
  }
  std::vector<SensorMessage> Messages(const std::string& /*instance*/, const std::any& /*settings*/,
                                      const SensorReading& reading, const MessageContext& context) const override {
    const Pose2D& pose = std::get<Pose2D>(reading);
    return {MessageOn(0, OdometryIn("world", context.frames->base, context.time, pose,
                                    InBody(context.velocity, context.truth.theta)))};
  }
};

}  // namespace

const SensorMessages& GroundTruthSensorMessages() {
  static const GroundTruthMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
