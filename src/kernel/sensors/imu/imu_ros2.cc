// The IMU as sensor_msgs/Imu on /<robot>/imu (or /<robot>/<instance>), in the frame
// <robot>/<instance> (the mount, with the robot's axes); without orientation its covariance's
// first element is -1, as the message's definition says.
#include "ros2_presentation/sensor_messages.h"
#include "sensors/imu/imu.h"

namespace sanet::ros2_presentation {
namespace {

using msg::sensor_msgs::Imu;

class ImuMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& instance, const std::any& /*settings*/) const override {
    return {TopicFor<Imu>(TopicName(instance, "imu", "imu"))};
  }
  std::vector<SensorMessage> Messages(const std::string& instance, const std::any& /*settings*/,
                                      const SensorReading& reading, const MessageContext& context) const override {
    const auto& r = std::get<ImuReading>(reading);
    Imu m;
    m.header.stamp = StampOf(context.time);
    m.header.frame_id = context.frames->Sensor(instance);
    if (r.orientation)
      m.orientation.x = r.orientation->x, m.orientation.y = r.orientation->y, m.orientation.z = r.orientation->z,
      m.orientation.w = r.orientation->w;
    m.angular_velocity.x = r.angular_velocity.x, m.angular_velocity.y = r.angular_velocity.y;
    m.angular_velocity.z = r.angular_velocity.z;
    m.linear_acceleration.x = r.linear_acceleration.x, m.linear_acceleration.y = r.linear_acceleration.y;
    m.linear_acceleration.z = r.linear_acceleration.z;
    for (std::size_t i = 0; i < 9; ++i) {
      m.orientation_covariance[i] = r.orientation_covariance[i];
      m.angular_velocity_covariance[i] = r.angular_velocity_covariance[i];
      m.linear_acceleration_covariance[i] = r.linear_acceleration_covariance[i];
    }
    return {MessageOn(0, m)};
  }
  void Mounts(const std::string& instance, const std::any& settings, const RobotFrames& frames, double t,
              std::vector<msg::geometry_msgs::TransformStamped>& out) const override {
    const auto& s = std::any_cast<const sensors::ImuSettings&>(settings);
    out.push_back(Transform(frames.base, frames.Sensor(instance), t, s.mount_x, s.mount_y, 0, 0));
  }
};

}  // namespace

const SensorMessages& ImuSensorMessages() {
  static const ImuMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
