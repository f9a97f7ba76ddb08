// The satellite fix as USARSim's GPS sensor writes it (its GPSSensor class):
// SEN {Time t} {Type GPS} {Name GPS} {Latitude 47,40.332312,N} {Longitude 122,18.597712,W}
// {Fix 1} {Satellites 8}, and without a fix {Name GPS} {Fix 0} {Satellites 0}: degrees, minutes
// and hemisphere. USARSim writes a minute's fraction to 4 decimals (0.19 m of latitude); these
// lines carry 6 (2 mm), which its readers parse alike. sanet models no constellation: a fix is
// said to see 8 satellites (a fix needs 4). A sanet extension field, {Altitude a} in m above the
// ellipsoid, follows, since USARSim's line has none; readers that look fields up by key pass
// over it.
#include <cmath>
#include <cstdio>
#include <limits>

#include "sensors/gnss/gnss.h"
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

constexpr int kSatellites = 8;

// "47,40.332312,N" for 47.672205 degrees with hemispheres `positive`, `negative`.
std::string DegreesMinutes(double degrees, char positive, char negative) {
  const double magnitude = std::fabs(degrees);
  double whole = std::floor(magnitude);
  double minutes = (magnitude - whole) * 60;
  if (std::round(minutes * 1e6) >= 60e6) whole += 1, minutes = 0;  // 59.9999996 prints as 60
  char text[64];
  std::snprintf(text, sizeof text, "%.0f,%.6f,%c", whole, minutes, degrees < 0 ? negative : positive);
  return text;
}

// "47,40.332312,N" back to degrees; nothing unless it is whole degrees up to `most`, minutes in
// [0, 60), one of the hemispheres and nothing after.
std::optional<double> Degrees(const std::string* text, char positive, char negative, double most) {
  if (!text) return std::nullopt;
  double whole = 0, minutes = 0;
  char hemisphere = 0;
  int end = 0;
  if (std::sscanf(text->c_str(), "%lf,%lf,%c%n", &whole, &minutes, &hemisphere, &end) != 3 ||
      static_cast<std::size_t>(end) != text->size())
    return std::nullopt;
  if (hemisphere != positive && hemisphere != negative) return std::nullopt;
  if (!(whole >= 0 && whole == std::floor(whole) && minutes >= 0 && minutes < 60)) return std::nullopt;
  const double degrees = whole + minutes / 60;
  if (degrees > most) return std::nullopt;
  return hemisphere == negative ? -degrees : degrees;
}

class GpsLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    const auto& r = std::get<FixReading>(reading);
    ProtocolMessage line = SenLine(context.time, "GPS");
    line.Add("Name", WireName(instance, "gnss", "GPS"));
    if (r.status == FixReading::kNoFix) return {line.Add("Fix", "0").Add("Satellites", "0")};
    line.Add("Latitude", DegreesMinutes(r.latitude, 'N', 'S')).Add("Longitude", DegreesMinutes(r.longitude, 'E', 'W'));
    line.Add("Fix", "1").Add("Satellites", std::to_string(kSatellites)).Add("Altitude", FormatPrecise(r.altitude));
    return {line};
  }
  bool IsFrom(const ProtocolMessage& line, const std::string& instance) const override {
    return NamesInstance(line, "GPS", instance, "gnss", "GPS");
  }
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& settings,
                                    const LineContext& /*context*/) const override {
    const auto fix = line.Count("Fix", 1);
    if (!fix) return std::nullopt;
    FixReading r;
    r.latitude = r.longitude = r.altitude = std::numeric_limits<double>::quiet_NaN();
    if (*fix == 0) return r;  // status kNoFix
    const auto latitude = Degrees(line.Get("Latitude"), 'N', 'S', 90);
    const auto longitude = Degrees(line.Get("Longitude"), 'E', 'W', 180);
    if (!latitude || !longitude) return std::nullopt;
    r.latitude = *latitude, r.longitude = *longitude, r.status = FixReading::kFix;
    if (const auto altitude = line.Number("Altitude"); altitude && std::isfinite(*altitude)) r.altitude = *altitude;
    const auto& s = std::any_cast<const sensors::GnssSettings&>(settings);
    r.position_covariance[0] = r.position_covariance[4] = s.horizontal_noise * s.horizontal_noise;
    r.position_covariance[8] = s.vertical_noise * s.vertical_noise;
    return r;
  }
};

}  // namespace

const SensorLines& GnssSensorLines() {
  static const GpsLines lines;
  return lines;
}

}  // namespace sanet::wire
