// The bearing sensor has no ROS 2 message (ROS has no standard one for range and bearing to
// named nodes): no topics, nothing published.
#include "ros2_presentation/sensor_messages.h"

namespace sanet::ros2_presentation {
namespace {

class BearingMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& /*instance*/, const std::any& /*settings*/) const override {
    return {};
  }
  std::vector<SensorMessage> Messages(const std::string& /*instance*/, const std::any& /*settings*/,
                                      const SensorReading& /*reading*/,
                                      const MessageContext& /*context*/) const override {
    return {};
  }
};

}  // namespace

const SensorMessages& BearingSensorMessages() {
  static const BearingMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
