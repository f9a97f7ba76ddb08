// The IR ring's topics (/<robot>/ir_<i>, or /<robot>/<instance>_<i>), messages and mounts.
#include "sensors/ir/ir_ros2.h"

#include <cmath>

#include "ros2_presentation/sensor_messages.h"
#include "sensors/range_fan.h"
#include "sensors/range_fan_ros2.h"

namespace sanet::ros2_presentation {

msg::sensor_msgs::Range RangeOf(const RangeScan& ir, std::size_t i, double t, const std::string& frame, double noise) {
  msg::sensor_msgs::Range r;
  r.header.stamp = StampOf(t);
  r.header.frame_id = frame;
  r.radiation_type = msg::sensor_msgs::Range::INFRARED;
  r.field_of_view = 0;
  r.min_range = 0;
  r.max_range = static_cast<float>(ir.max_range);
  r.range = NothingSeenAsInfinity(ir.ranges.at(i), ir.max_range);
  r.variance = static_cast<float>(noise * noise);
  return r;
}

namespace {

// Sensor i's topic and frame: ir_<i>, or <instance>_<i> for a named instance.
std::string SensorName(const std::string& instance, std::size_t i) { return instance + "_" + std::to_string(i); }

class IrMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& instance, const std::any& settings) const override {
    std::vector<SensorTopic> topics;
    const auto& ir = std::any_cast<const sensors::RangeFan&>(settings);
    for (std::size_t i = 0; i < ir.angles.size(); ++i)
      topics.push_back(TopicFor<msg::sensor_msgs::Range>(SensorName(instance, i)));
    return topics;
  }
  std::vector<SensorMessage> Messages(const std::string& instance, const std::any& settings,
                                      const SensorReading& reading, const MessageContext& context) const override {
    const auto& ir = std::any_cast<const sensors::RangeFan&>(settings);
    const RangeScan& scan = std::get<RangeScan>(reading);
    std::vector<SensorMessage> out;
    for (std::size_t i = 0; i < scan.ranges.size() && i < ir.angles.size(); ++i)
      out.push_back(
          MessageOn(i, RangeOf(scan, i, context.time, context.frames->Sensor(SensorName(instance, i)), ir.noise)));
    return out;
  }
  void Mounts(const std::string& instance, const std::any& settings, const RobotFrames& frames, double t,
              std::vector<msg::geometry_msgs::TransformStamped>& out) const override {
    const auto& ir = std::any_cast<const sensors::RangeFan&>(settings);
    for (std::size_t i = 0; i < ir.angles.size(); ++i) {
      const double a = ir.angles[i];
      out.push_back(Transform(frames.base, frames.Sensor(SensorName(instance, i)), t,
                              ir.mount_x + ir.mount_radius * std::cos(a), ir.mount_radius * std::sin(a),
                              ir.mount_height, a));
    }
  }
};

}  // namespace

const SensorMessages& IrSensorMessages() {
  static const IrMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
