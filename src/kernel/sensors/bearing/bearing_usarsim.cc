// sanet extension: SEN {Time t} {Type Bearing} [{Instance i}] {Name R Distance d Bearing b} ...,
// one Name per node within the sensor's range, the angle in USARSim's frame (clockwise: left is
// negative). {Instance i} names a named instance (none for the kind's own).
#include <cstdio>

#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

class BearingLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    ProtocolMessage line = SenLine(context.time, "Bearing");
    if (instance != "bearing") line.Add("Instance", instance);
    for (const NodeBearing& b : std::get<BearingsReading>(reading).in_range)
      line.Add("Name", context.name_of(b.node) + " Distance " + FormatNumber(b.reading.distance) + " Bearing " +
                           FormatNumber(-b.reading.bearing));
    return {line};
  }
  bool IsFrom(const ProtocolMessage& line, const std::string& instance) const override {
    const std::string *type = line.Get("Type"), *named = line.Get("Instance");
    return type && *type == "Bearing" && (named ? *named : std::string("bearing")) == instance;
  }
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& /*settings*/,
                                    const LineContext& context) const override {
    BearingsReading out;
    for (const auto& [key, value] : line.fields) {
      if (key != "Name") continue;
      char name[128];
      double distance = 0, angle = 0;
      if (std::sscanf(value.c_str(), "%127s Distance %lf Bearing %lf", name, &distance, &angle) != 3) continue;
      if (const auto node = context.lookup(name)) out.in_range.push_back({*node, BearingReading{distance, -angle}});
    }
    return out;
  }
  bool Extension() const override { return true; }
};

}  // namespace

const SensorLines& BearingSensorLines() {
  static const BearingLines lines;
  return lines;
}

}  // namespace sanet::wire
