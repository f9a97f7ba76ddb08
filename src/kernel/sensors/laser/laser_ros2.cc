// The laser's topic (/<robot>/scan, or /<robot>/<instance>), message and mount.
#include "sensors/laser/laser_ros2.h"

#include "ros2_presentation/sensor_messages.h"
#include "sensors/range_fan.h"
#include "sensors/range_fan_ros2.h"

namespace sanet::ros2_presentation {

msg::sensor_msgs::LaserScan ScanOf(const RangeScan& scan, double t, const std::string& frame) {
  msg::sensor_msgs::LaserScan s;
  s.header.stamp = StampOf(t);
  s.header.frame_id = frame;
  if (!scan.angles.empty()) {
    s.angle_min = static_cast<float>(scan.angles.front());
    s.angle_max = static_cast<float>(scan.angles.back());
    if (scan.angles.size() > 1)
      s.angle_increment = static_cast<float>((scan.angles.back() - scan.angles.front()) / (scan.angles.size() - 1));
  }
  s.range_min = 0;
  s.range_max = static_cast<float>(scan.max_range);
  s.ranges.reserve(scan.ranges.size());
  for (double range : scan.ranges) s.ranges.push_back(NothingSeenAsInfinity(range, scan.max_range));
  return s;
}

namespace {

// Its frame: <robot>/laser for the kind's own instance, <robot>/<instance> for a named one.
std::string FrameName(const std::string& instance) { return TopicName(instance, "laser", "laser"); }

class LaserMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& instance, const std::any& /*settings*/) const override {
    return {TopicFor<msg::sensor_msgs::LaserScan>(TopicName(instance, "laser", "scan"))};
  }
  std::vector<SensorMessage> Messages(const std::string& instance, const std::any& settings,
                                      const SensorReading& reading, const MessageContext& context) const override {
    const std::string frame = context.frames->Sensor(FrameName(instance));
    const double direction = std::any_cast<const sensors::RangeFan&>(settings).direction;
    if (direction == 0) return {MessageOn(0, ScanOf(std::get<RangeScan>(reading), context.time, frame))};
    RangeScan in_its_frame = std::get<RangeScan>(reading);  // a turned laser's frame is turned with it
    for (double& angle : in_its_frame.angles) angle -= direction;
    return {MessageOn(0, ScanOf(in_its_frame, context.time, frame))};
  }
  void Mounts(const std::string& instance, const std::any& settings, const RobotFrames& frames, double t,
              std::vector<msg::geometry_msgs::TransformStamped>& out) const override {
    const auto& laser = std::any_cast<const sensors::RangeFan&>(settings);
    out.push_back(Transform(frames.base, frames.Sensor(FrameName(instance)), t, laser.mount_x, 0, laser.mount_height,
                            laser.direction));
  }
};

}  // namespace

const SensorMessages& LaserSensorMessages() {
  static const LaserMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
