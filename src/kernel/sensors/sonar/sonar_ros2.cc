// The sonar as sensor_msgs/Range (ULTRASOUND, the cone's width as its field of view) on
// /<robot>/sonar (or /<robot>/<instance>), in frame <robot>/sonar at the cone's start.
#include <cmath>

#include "ros2_presentation/sensor_messages.h"
#include "sensors/range_fan_ros2.h"
#include "sensors/sonar/sonar.h"

namespace sanet::ros2_presentation {
namespace {

class SonarMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& instance, const std::any& /*settings*/) const override {
    return {TopicFor<msg::sensor_msgs::Range>(TopicName(instance, "sonar", "sonar"))};
  }
  std::vector<SensorMessage> Messages(const std::string& instance, const std::any& settings,
                                      const SensorReading& reading, const MessageContext& context) const override {
    const auto& sonar = std::any_cast<const sensors::SonarSettings&>(settings);
    const RangeScan& echo = std::get<RangeScan>(reading);
    msg::sensor_msgs::Range r;
    r.header.stamp = StampOf(context.time);
    r.header.frame_id = context.frames->Sensor(TopicName(instance, "sonar", "sonar"));
    r.radiation_type = msg::sensor_msgs::Range::ULTRASOUND;
    r.field_of_view = static_cast<float>(sonar.fov);
    r.min_range = 0;
    r.max_range = static_cast<float>(sonar.max_range);
    r.range = NothingSeenAsInfinity(echo.ranges.at(0), sonar.max_range);
    r.variance = static_cast<float>(sonar.noise * sonar.noise);
    return {MessageOn(0, r)};
  }
  void Mounts(const std::string& instance, const std::any& settings, const RobotFrames& frames, double t,
              std::vector<msg::geometry_msgs::TransformStamped>& out) const override {
    const auto& s = std::any_cast<const sensors::SonarSettings&>(settings);
    out.push_back(Transform(frames.base, frames.Sensor(TopicName(instance, "sonar", "sonar")), t,
                            s.mount_radius * std::cos(s.direction), s.mount_radius * std::sin(s.direction), s.height,
                            s.direction));
  }
};

}  // namespace

const SensorMessages& SonarSensorMessages() {
  static const SonarMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
