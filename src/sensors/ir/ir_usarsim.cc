// The IR ring as one USARSim sonar-style line: {Name IR0 Range r} {Name IR1 Range r} ...; a named
// instance's sensors are <instance>0, <instance>1, ...
#include <cctype>
#include <cstdlib>

#include "sensors/range_fan.h"
#include "wire/sensor_lines.h"

namespace sanet::hil {
namespace {

// "IR3" -> "IR"; "ir_low12" -> "ir_low".
std::string Prefix(const std::string& sensor) {
  std::size_t end = sensor.size();
  while (end > 0 && std::isdigit(static_cast<unsigned char>(sensor[end - 1]))) --end;
  return sensor.substr(0, end);
}

class IrLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    const RangeScan& scan = std::get<RangeScan>(reading);
    ProtocolMessage line = SenLine(context.time, "IR");
    const std::string prefix = WireName(instance, "ir", "IR");
    for (std::size_t i = 0; i < scan.ranges.size(); ++i)
      line.Add("Name", prefix + std::to_string(i) + " Range " + FormatNumber(scan.ranges[i]));
    return {line};
  }
  std::optional<std::string> InstanceOf(const ProtocolMessage& line) const override {
    const std::string *type = line.Get("Type"), *name = line.Get("Name");
    if (!type || *type != "IR") return std::nullopt;
    const std::string sensor = name ? name->substr(0, name->find(' ')) : "IR0";
    return InstanceNamed(Prefix(sensor), "ir", "IR");
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

}  // namespace sanet::hil
