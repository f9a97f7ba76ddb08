// Ground truth as USARSim's GroundTruth sensor: {Location x,y,z} {Orientation roll,pitch,yaw}.
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

class GroundTruthLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    const auto p = UsarsimPose(std::get<Pose2D>(reading));
    return {SenLine(context.time, "GroundTruth")
                .Add("Name", WireName(instance, "ground_truth", "GroundTruth"))
                .Add("Location", std::vector<double>{p[0], p[1], context.height})
                .Add("Orientation", std::vector<double>{0, 0, p[2]})};
  }
  bool IsFrom(const ProtocolMessage& line, const std::string& instance) const override {
    return NamesInstance(line, "GroundTruth", instance, "ground_truth", "GroundTruth");
  }
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& /*settings*/,
                                    const LineContext& /*context*/) const override {
    const auto at = line.Numbers("Location"), o = line.Numbers("Orientation");
    if (!at || !o || at->size() < 2 || o->size() < 3) return std::nullopt;
    return SanetPose((*at)[0], (*at)[1], (*o)[2]);
  }
};

}  // namespace

const SensorLines& GroundTruthSensorLines() {
  static const GroundTruthLines lines;
  return lines;
}

}  // namespace sanet::wire
