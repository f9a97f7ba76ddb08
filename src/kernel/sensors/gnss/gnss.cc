// The satellite fix's kernel part (sensors/gnss/gnss.h).
#include "sensors/gnss/gnss.h"

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sensors/sampling_sensor.h"
#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class Receiver : public SamplingSensor {
 public:
  Receiver(GnssSettings settings, Mount mount)
      : SamplingSensor(settings.rate, mount.world),
        settings_(settings),
        mount_(mount),
        datum_(mount.surroundings.datum->latitude, mount.surroundings.datum->longitude,
               mount.surroundings.datum->altitude) {}

 private:
  SensorReading Sample(double period) override {
    Wander(period);
    return Fix();
  }

  // The error's next value: e' = phi e + sigma sqrt(1 - phi^2) w, phi = exp(-period / tau); white
  // (phi = 0) without a correlation time. The first sample starts from the stationary spread.
  void Wander(double period) {
    const double phi = started_ && settings_.correlation_time > 0 ? std::exp(-period / settings_.correlation_time) : 0;
    const double fresh = std::sqrt(1 - phi * phi);
    const double sigma[3] = {settings_.horizontal_noise, settings_.horizontal_noise, settings_.vertical_noise};
    for (int i = 0; i < 3; ++i) error_[i] = phi * error_[i] + mount_.random.Gaussian(0, sigma[i] * fresh);
    started_ = true;
  }

  FixReading Fix() const {
    const Pose2D pose = mount_.model.body().pose();
    const double c = std::cos(pose.theta), s = std::sin(pose.theta);
    const Vec2 antenna{pose.x + c * settings_.mount_x - s * settings_.mount_y,
                       pose.y + s * settings_.mount_x + c * settings_.mount_y};
    FixReading r;
    if (mount_.surroundings.Denied(antenna)) {
      r.status = FixReading::kNoFix;
      r.latitude = r.longitude = r.altitude = std::numeric_limits<double>::quiet_NaN();
      return r;
    }
    datum_.Reverse(antenna.x + error_[0], antenna.y + error_[1], settings_.height + error_[2], r.latitude, r.longitude,
                   r.altitude);
    r.status = FixReading::kFix;
    const double h = settings_.horizontal_noise * settings_.horizontal_noise;
    r.position_covariance[0] = r.position_covariance[4] = h;
    r.position_covariance[8] = settings_.vertical_noise * settings_.vertical_noise;
    return r;
  }

  GnssSettings settings_;
  Mount mount_;
  GeographicLib::LocalCartesian datum_;
  double error_[3] = {0, 0, 0};  // m: east, north, up
  bool started_ = false;
};

class SatelliteFix : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"gnss",
                                 "a satellite position fix through the world's datum, with noise; none indoors",
                                 "FixReading",
                                 "latitude and longitude in degrees, altitude in m above the WGS 84 ellipsoid, "
                                 "covariance in m^2 (east, north, up)",
                                 "sensor_msgs/msg/NavSatFix",
                                 "fix"};
    return info;
  }
  std::any DefaultSettings(const robots::ModelSpec& /*model*/) const override { return GnssSettings{}; }
  bool SamplesOnItsOwn() const override { return true; }
  std::optional<std::string> RefusesWorld(const Surroundings& world) const override {
    if (world.datum) return std::nullopt;
    return "a satellite fix needs the world's place on the Earth: give `world.datum: {latitude, longitude, "
           "altitude}` (the world's origin; its x points east, y north)";
  }
  std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const override {
    if (const auto why = RefusesWorld(mount.surroundings)) throw std::invalid_argument(*why);
    return std::make_unique<Receiver>(std::any_cast<GnssSettings>(settings), mount);
  }
};

}  // namespace

const SensorKind& GnssKind() {
  static const SatelliteFix kind;
  return kind;
}

}  // namespace sanet::sensors
