// The battery on the robot protocol, as a line of sanet's own (USARSim reports a battery only as
// the seconds left in its STA lines): SEN {Type Battery} {Name battery} {Remaining J}
// {Capacity J} {Voltage V} {Power W} {Charging False}, numbers with all their digits.
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

bool Charging(const ProtocolMessage& line) {
  const std::string* charging = line.Get("Charging");
  return charging && *charging == "True";
}

class BatteryLines : public SensorLines {
 public:
  bool Extension() const override { return true; }  // USARSim's own clients read STA's Battery
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    const auto& b = std::get<BatteryReading>(reading);
    return {SenLine(context.time, "Battery")
                .Add("Name", WireName(instance, "battery", "battery"))
                .Add("Remaining", FormatPrecise(b.remaining_j))
                .Add("Capacity", FormatPrecise(b.capacity_j))
                .Add("Voltage", FormatPrecise(b.voltage))
                .Add("Power", FormatPrecise(b.power_w))
                .Add("Charging", b.charging ? "True" : "False")};
  }
  bool IsFrom(const ProtocolMessage& line, const std::string& instance) const override {
    return NamesInstance(line, "Battery", instance, "battery", "battery");
  }
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& /*settings*/,
                                    const LineContext& /*context*/) const override {
    const auto remaining = line.Number("Remaining"), capacity = line.Number("Capacity");
    const auto voltage = line.Number("Voltage"), power = line.Number("Power");
    if (!remaining || !capacity || !voltage || !power || *capacity <= 0) return std::nullopt;
    return BatteryReading{*remaining, *remaining / *capacity, *voltage, Charging(line), *capacity, *power};
  }
};

}  // namespace

const SensorLines& BatterySensorLines() {
  static const BatteryLines lines;
  return lines;
}

}  // namespace sanet::wire
