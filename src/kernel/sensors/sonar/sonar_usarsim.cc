// The sonar as USARSim's Sonar sensor, in the grouped form: SEN {Type Sonar} {Name Sonar Range r}
// (a named instance: {Name <instance> Range r}).
#include <cstdio>

#include "sensors/sonar/sonar.h"
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

class SonarLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    const RangeScan& echo = std::get<RangeScan>(reading);
    return {SenLine(context.time, "Sonar")
                .Add("Name", WireName(instance, "sonar", "Sonar") + " Range " + FormatNumber(echo.ranges.at(0)))};
  }
  bool IsFrom(const ProtocolMessage& line, const std::string& instance) const override {
    const std::string *type = line.Get("Type"), *name = line.Get("Name");
    return type && *type == "Sonar" && name && name->substr(0, name->find(' ')) == WireName(instance, "sonar", "Sonar");
  }
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& settings,
                                    const LineContext& /*context*/) const override {
    const auto& sonar = std::any_cast<const sensors::SonarSettings&>(settings);
    double range = 0;
    const std::string* name = line.Get("Name");
    if (!name || std::sscanf(name->c_str(), "%*s Range %lf", &range) != 1) return std::nullopt;
    return RangeScan{{sonar.direction}, {range}, sonar.max_range};
  }
};

}  // namespace

const SensorLines& SonarSensorLines() {
  static const SonarLines lines;
  return lines;
}

}  // namespace sanet::wire
