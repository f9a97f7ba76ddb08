// The encoders as USARSim's Encoder sensors, in the grouped form its sources write:
// SEN {Time t} {Type Encoder} {Name ECLeft Tick n} {Name ECRight Tick m}: a wheel's angle as a
// count of ticks of a milliradian (the lines carry no resolution: a scenario's `resolution`
// rounds the angle before it is counted). A differential drive's wheels are ECLeft and
// ECRight, an omni3's EC0 to EC2.
#include <cmath>
#include <cstdio>

#include "sensors/encoders/encoders.h"
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

constexpr double kTick = 1e-3;  // rad

std::string WheelName(std::size_t i, std::size_t wheels) {
  if (wheels == 2) return i == 0 ? "ECLeft" : "ECRight";
  return "EC" + std::to_string(i);
}

class EncoderLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& /*instance*/, const SensorReading& reading,
                                     const LineContext& context) const override {
    const auto& joints = std::get<JointStatesReading>(reading);
    ProtocolMessage line = SenLine(context.time, "Encoder");
    for (std::size_t i = 0; i < joints.angles.size(); ++i)
      line.Add("Name",
               WheelName(i, joints.angles.size()) + " Tick " + std::to_string(std::llround(joints.angles[i] / kTick)));
    return {line};
  }
  bool IsFrom(const ProtocolMessage& line, const std::string& /*instance*/) const override {
    const std::string* type = line.Get("Type");
    return type && *type == "Encoder";
  }
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& settings,
                                    const LineContext& /*context*/) const override {
    const auto& s = std::any_cast<const sensors::EncodersSettings&>(settings);
    JointStatesReading r;
    for (const auto& [key, value] : line.fields) {
      if (key != "Name") continue;
      long long ticks = 0;
      if (std::sscanf(value.c_str(), "%*s Tick %lld", &ticks) != 1) return std::nullopt;
      r.names.push_back(r.names.size() < s.names.size() ? s.names[r.names.size()] : value.substr(0, value.find(' ')));
      r.angles.push_back(static_cast<double>(ticks) * kTick);
      r.speeds.push_back(0);  // the line carries counts only
    }
    return r;
  }
};

}  // namespace

const SensorLines& EncodersSensorLines() {
  static const EncoderLines lines;
  return lines;
}

}  // namespace sanet::wire
