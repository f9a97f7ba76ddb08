// The laser as USARSim's RangeScanner: {Resolution r} {FOV f} {Range r0,r1,...}, right to left.
#include "sensors/range_fan.h"
#include "wire/sensor_lines.h"

namespace sanet::hil {
namespace {

class LaserLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    const RangeScan& scan = std::get<RangeScan>(reading);
    const double resolution = scan.angles.size() > 1 ? scan.angles[1] - scan.angles[0] : 0;
    const double fov = scan.angles.empty() ? 0 : scan.angles.back() - scan.angles.front();
    return {SenLine(context.time, "RangeScanner")
                .Add("Name", WireName(instance, "laser", "Scanner1"))
                .Add("Resolution", resolution)
                .Add("FOV", fov)
                .Add("Range", scan.ranges)};
  }
  std::optional<std::string> InstanceOf(const ProtocolMessage& line) const override {
    const std::string *type = line.Get("Type"), *name = line.Get("Name");
    if (!type || *type != "RangeScanner") return std::nullopt;
    return InstanceNamed(name ? *name : "Scanner1", "laser", "Scanner1");
  }
  // The directions from the line's FOV, the range limit from the scenario.
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& settings,
                                    const LineContext& /*context*/) const override {
    const auto ranges = line.Numbers("Range");
    const auto fov = line.Number("FOV");
    if (!ranges || !fov || ranges->empty()) return std::nullopt;
    RangeScan scan;
    scan.ranges = *ranges;
    scan.max_range = std::any_cast<const sensors::RangeFan&>(settings).max_range;
    for (std::size_t i = 0; i < ranges->size(); ++i)
      scan.angles.push_back(ranges->size() == 1 ? 0 : -*fov / 2 + *fov * i / (ranges->size() - 1));
    return scan;
  }
};

}  // namespace

const SensorLines& LaserSensorLines() {
  static const LaserLines lines;
  return lines;
}

}  // namespace sanet::hil
