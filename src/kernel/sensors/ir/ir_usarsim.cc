// The IR ring as one USARSim sonar-style line: {Name IR0 Range r} {Name IR1 Range r} ...; a named
// instance's sensors are <instance>0, <instance>1, ...
#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "sensors/range_fan.h"
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

// Sensor i of instance `instance` on the wire: IR<i> for the kind's own ring (USARSim's names),
// <instance>_<i> for a named one, so that no name is another's with digits added.
std::string SensorName(const std::string& instance, std::size_t i) {
  return instance == "ir" ? "IR" + std::to_string(i) : instance + "_" + std::to_string(i);
}

// Whether `sensor` (the first word of a {Name ...}) is one of `instance`'s: its prefix and digits.
bool IsSensorOf(const std::string& sensor, const std::string& instance) {
  const std::string prefix = instance == "ir" ? "IR" : instance + "_";
  if (sensor.size() <= prefix.size() || sensor.compare(0, prefix.size(), prefix) != 0) return false;
  return std::all_of(sensor.begin() + static_cast<std::ptrdiff_t>(prefix.size()), sensor.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

class IrLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    const RangeScan& scan = std::get<RangeScan>(reading);
    ProtocolMessage line = SenLine(context.time, "IR");
    for (std::size_t i = 0; i < scan.ranges.size(); ++i)
      line.Add("Name", SensorName(instance, i) + " Range " + FormatNumber(scan.ranges[i]));
    return {line};
  }
  bool IsFrom(const ProtocolMessage& line, const std::string& instance) const override {
    const std::string *type = line.Get("Type"), *name = line.Get("Name");
    return type && *type == "IR" && name && IsSensorOf(name->substr(0, name->find(' ')), instance);
  }
  // The directions and range limit from the scenario; a line with another count is not read.
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& settings,
                                    const LineContext& /*context*/) const override {
    const auto& ir = std::any_cast<const sensors::RangeFan&>(settings);
    RangeScan scan;
    scan.angles = ir.angles;
    scan.max_range = ir.max_range;
    for (const auto& [key, value] : line.fields)
      if (key == "Name") {
        const auto at = value.rfind(' ');
        scan.ranges.push_back(at == std::string::npos ? 0 : std::atof(value.c_str() + at + 1));
      }
    if (scan.ranges.size() != scan.angles.size()) return std::nullopt;
    return scan;
  }
};

}  // namespace

const SensorLines& IrSensorLines() {
  static const IrLines lines;
  return lines;
}

}  // namespace sanet::wire
