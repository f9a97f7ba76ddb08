#include "sensors/range_fan_fields.h"

#include "sanet/geometry.h"

namespace sanet::sensors {

YAML::Node AngleList(const std::vector<double>& angles) {
  YAML::Node out(YAML::NodeType::Sequence);
  for (double a : angles) out.push_back(scenario::NumberNode(a));
  out.SetStyle(YAML::EmitterStyle::Flow);
  return out;
}

std::vector<double> ReadAngles(const scenario::Field& field) {
  std::vector<double> angles;
  for (const scenario::Field& a : field.Items()) angles.push_back(a.Number(-2 * kPi, 2 * kPi));
  if (angles.empty()) field.Fail("needs at least one angle");
  return angles;
}

}  // namespace sanet::sensors
