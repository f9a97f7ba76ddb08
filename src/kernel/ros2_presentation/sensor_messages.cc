#include "ros2_presentation/sensor_messages.h"

namespace sanet::ros2_presentation {

const SensorMessages* MessagesOf(const std::string& kind) {
#define SANET_MESSAGES_IF(name, Name) \
  if (kind == #name) return &Name##SensorMessages();
  SANET_SENSOR_KINDS(SANET_MESSAGES_IF)
#undef SANET_MESSAGES_IF
  return nullptr;
}

}  // namespace sanet::ros2_presentation
