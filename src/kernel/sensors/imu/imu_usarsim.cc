// sanet extension: SEN {Time t} {Type IMU} [{Instance i}] {AngularVelocity x,y,z}
// {LinearAcceleration x,y,z} [{Orientation x,y,z,w}], in sanet's axes (REP 103: x forward, y
// left, z up), six decimals. USARSim has no such line: its INS sensor reports a pose it
// integrates, not the rates an IMU measures (docs/scenario.md#sensors). The covariances come
// from the scenario's noise at the reading end.
#include <cmath>

#include "sensors/imu/imu.h"
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

std::string Triple(const Vector3& v) {
  return FormatPrecise(v.x) + "," + FormatPrecise(v.y) + "," + FormatPrecise(v.z);
}

class ImuLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    const auto& r = std::get<ImuReading>(reading);
    ProtocolMessage line = SenLine(context.time, "IMU");
    if (instance != "imu") line.Add("Instance", instance);
    line.Add("AngularVelocity", Triple(r.angular_velocity)).Add("LinearAcceleration", Triple(r.linear_acceleration));
    if (r.orientation)
      line.Add("Orientation", FormatPrecise(r.orientation->x) + "," + FormatPrecise(r.orientation->y) + "," +
                                  FormatPrecise(r.orientation->z) + "," + FormatPrecise(r.orientation->w));
    return {line};
  }
  bool IsFrom(const ProtocolMessage& line, const std::string& instance) const override {
    const std::string *type = line.Get("Type"), *named = line.Get("Instance");
    return type && *type == "IMU" && (named ? *named : std::string("imu")) == instance;
  }
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& settings,
                                    const LineContext& /*context*/) const override {
    const auto w = line.Numbers("AngularVelocity"), a = line.Numbers("LinearAcceleration");
    if (!w || !a || w->size() != 3 || a->size() != 3) return std::nullopt;
    ImuReading r;
    r.angular_velocity = {(*w)[0], (*w)[1], (*w)[2]};
    r.linear_acceleration = {(*a)[0], (*a)[1], (*a)[2]};
    if (const auto q = line.Numbers("Orientation"); q && q->size() == 4)
      r.orientation = Quaternion{(*q)[0], (*q)[1], (*q)[2], (*q)[3]};
    else
      r.orientation_covariance[0] = -1;
    const auto& s = std::any_cast<const sensors::ImuSettings&>(settings);
    for (int i = 0; i < 3; ++i) {
      r.angular_velocity_covariance[4 * i] = std::pow(s.gyroscope_noise_density, 2) * s.rate;
      r.linear_acceleration_covariance[4 * i] = std::pow(s.accelerometer_noise_density, 2) * s.rate;
    }
    return r;
  }
  bool Extension() const override { return true; }
};

}  // namespace

const SensorLines& ImuSensorLines() {
  static const ImuLines lines;
  return lines;
}

}  // namespace sanet::wire
