// Odometry as USARSim's Odometry sensor: {Pose x,y,yaw}.
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

class OdometryLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    return {SenLine(context.time, "Odometry")
                .Add("Name", WireName(instance, "odometry", "Odometry"))
                .Add("Pose", UsarsimPose(std::get<Pose2D>(reading)))};
  }
  bool IsFrom(const ProtocolMessage& line, const std::string& instance) const override {
    return NamesInstance(line, "Odometry", instance, "odometry", "Odometry");
  }
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& /*settings*/,
                                    const LineContext& /*context*/) const override {
    const auto p = line.Numbers("Pose");
    if (!p || p->size() < 3) return std::nullopt;
    return SanetPose((*p)[0], (*p)[1], (*p)[2]);
  }
};

}  // namespace

const SensorLines& OdometrySensorLines() {
  static const OdometryLines lines;
  return lines;
}

}  // namespace sanet::wire
