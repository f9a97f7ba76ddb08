#include "wire/sensor_lines.h"

namespace sanet::wire {

const SensorLines* LinesOf(const std::string& kind) {
#define SANET_LINES_IF(name, Name) \
  if (kind == #name) return &Name##SensorLines();
  SANET_SENSOR_KINDS(SANET_LINES_IF)
#undef SANET_LINES_IF
  return nullptr;
}

std::vector<double> UsarsimPose(const Pose2D& p) { return {p.x, -p.y, -p.theta}; }

Pose2D SanetPose(double x, double y, double yaw) { return {x, -y, -yaw}; }

ProtocolMessage SenLine(double time, const std::string& type) {
  return ProtocolMessage{"SEN"}.Add("Time", FormatNumber(time)).Add("Type", type);
}

std::string WireName(const std::string& instance, const std::string& kind, const std::string& usarsim_name) {
  return instance == kind ? usarsim_name : instance;
}

bool NamesInstance(const ProtocolMessage& line, const std::string& type, const std::string& instance,
                   const std::string& kind, const std::string& usarsim_name) {
  const std::string *line_type = line.Get("Type"), *name = line.Get("Name");
  return line_type && *line_type == type && name && *name == WireName(instance, kind, usarsim_name);
}

}  // namespace sanet::wire
