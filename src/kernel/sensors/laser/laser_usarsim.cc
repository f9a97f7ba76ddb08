// The laser as USARSim's RangeScanner: {Resolution r} {FOV f} {Range r0,r1,...}, right to left.
#include "sensors/range_fan.h"
#include "wire/sensor_lines.h"

namespace sanet::wire {
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
  bool IsFrom(const ProtocolMessage& line, const std::string& instance) const override {
    return NamesInstance(line, "RangeScanner", instance, "laser", "Scanner1");
  }
  // The directions from the scenario's laser (from the line's FOV, evenly, if the counts differ),
  // as is the range limit.
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& settings,
                                    const LineContext& /*context*/) const override {
    const auto ranges = line.Numbers("Range");
    const auto fov = line.Number("FOV");
    if (!ranges || !fov || ranges->empty()) return std::nullopt;
    const auto& laser = std::any_cast<const sensors::RangeFan&>(settings);
    RangeScan scan;
    scan.ranges = *ranges;
    scan.max_range = laser.max_range;
    const std::size_t n = ranges->size();
    for (std::size_t i = 0; i < n; ++i)
      scan.angles.push_back(n == laser.angles.size() ? laser.angles[i] : n == 1 ? 0 : -*fov / 2 + *fov * i / (n - 1));
    if (laser.direction != 0)
      for (double& angle : scan.angles) angle += laser.direction;
    return scan;
  }
};

}  // namespace

const SensorLines& LaserSensorLines() {
  static const LaserLines lines;
  return lines;
}

}  // namespace sanet::wire
