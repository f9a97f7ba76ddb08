// The satellite fix as sensor_msgs/NavSatFix on /<robot>/fix (or /<robot>/<instance>), in the
// frame <robot>/<instance> (the antenna, mounted in /tf_static): status STATUS_FIX with service
// SERVICE_GPS, and a diagonal covariance of the scenario's noise (COVARIANCE_TYPE_DIAGONAL_KNOWN);
// without a fix STATUS_NO_FIX, NaN position and COVARIANCE_TYPE_UNKNOWN.
#include "ros2_presentation/sensor_messages.h"
#include "sensors/gnss/gnss.h"

namespace sanet::ros2_presentation {
namespace {

using msg::sensor_msgs::NavSatFix;

constexpr std::uint16_t kServiceGps = 1;
constexpr std::uint8_t kCovarianceUnknown = 0, kCovarianceDiagonalKnown = 2;

class GnssMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& instance, const std::any& /*settings*/) const override {
    return {TopicFor<NavSatFix>(TopicName(instance, "gnss", "fix"))};
  }
  std::vector<SensorMessage> Messages(const std::string& instance, const std::any& /*settings*/,
                                      const SensorReading& reading, const MessageContext& context) const override {
    const auto& r = std::get<FixReading>(reading);
    NavSatFix m;
    m.header.stamp = StampOf(context.time);
    m.header.frame_id = context.frames->Sensor(instance);
    m.status.status = static_cast<std::int8_t>(r.status);
    m.status.service = kServiceGps;
    m.latitude = r.latitude, m.longitude = r.longitude, m.altitude = r.altitude;
    for (std::size_t i = 0; i < 9; ++i) m.position_covariance[i] = r.position_covariance[i];
    m.position_covariance_type = r.status == FixReading::kNoFix ? kCovarianceUnknown : kCovarianceDiagonalKnown;
    return {MessageOn(0, m)};
  }
  void Mounts(const std::string& instance, const std::any& settings, const RobotFrames& frames, double t,
              std::vector<msg::geometry_msgs::TransformStamped>& out) const override {
    const auto& s = std::any_cast<const sensors::GnssSettings&>(settings);
    out.push_back(Transform(frames.base, frames.Sensor(instance), t, s.mount_x, s.mount_y, s.height, 0));
  }
};

}  // namespace

const SensorMessages& GnssSensorMessages() {
  static const GnssMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
