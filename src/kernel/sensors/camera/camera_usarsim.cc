// The camera has no SEN line yet: USARSim serves pictures on a port of its own (its image server),
// not in the robot protocol, and agents will get them in a later step (docs/scenario.md#sensors).
#include "sensors/camera/camera.h"
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

class NoCameraLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& /*instance*/, const SensorReading& /*reading*/,
                                     const LineContext& /*context*/) const override {
    return {};
  }
  bool IsFrom(const ProtocolMessage& /*line*/, const std::string& /*instance*/) const override { return false; }
  std::optional<SensorReading> Read(const ProtocolMessage& /*line*/, const std::any& /*settings*/,
                                    const LineContext& /*context*/) const override {
    return std::nullopt;
  }
};

}  // namespace

const SensorLines& CameraSensorLines() {
  static const NoCameraLines lines;
  return lines;
}

}  // namespace sanet::wire
