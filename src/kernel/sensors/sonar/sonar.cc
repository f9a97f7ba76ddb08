// The sonar's kernel part: a fan of rays over the cone (sensors/range_fan.h), of which the
// nearest hit is the range.
#include "sensors/sonar/sonar.h"

#include <algorithm>

#include "sensors/range_fan.h"
#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class Echo : public SensorInstance {
 public:
  Echo(const SonarSettings& settings, Mount mount) : settings_(settings), mount_(mount), rays_(Rays(settings), mount) {}

  // One range at the cone's direction: the nearest of the rays, then the noise, clamped.
  std::optional<SensorReading> Read(const ReadContext& context) override {
    const RangeScan cone = std::get<RangeScan>(*rays_.Read(context));
    RangeScan echo;
    echo.angles = {settings_.direction};
    echo.max_range = settings_.max_range;
    double nearest = *std::min_element(cone.ranges.begin(), cone.ranges.end());
    if (settings_.noise > 0)
      nearest = std::clamp(mount_.random.Gaussian(nearest, settings_.noise), 0.0, settings_.max_range);
    echo.ranges = {nearest};
    return echo;
  }

 private:
  static RangeFan Rays(const SonarSettings& s) {
    RangeFan fan = RangeFan::Fan(s.fov, s.rays, 0, s.height, s.max_range);
    fan.direction = s.direction;
    fan.mount_radius = s.mount_radius;
    return fan;
  }
  SonarSettings settings_;
  Mount mount_;
  RangeFanSensor rays_;  // noiseless: the noise is the echo's
};

class Sonar : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"sonar",
                                 "an ultrasonic range finder: the nearest thing within a cone",
                                 "RangeScan",
                                 "one range in m, at the cone's direction in rad",
                                 "sensor_msgs/msg/Range (ULTRASOUND)",
                                 "sonar"};
    return info;
  }
  // Forward, at the body's edge.
  std::any DefaultSettings(const robots::ModelSpec& model) const override {
    SonarSettings s;
    s.mount_radius = robots::EdgeRadius(model);
    return s;
  }
  std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const override {
    return std::make_unique<Echo>(std::any_cast<const SonarSettings&>(settings), mount);
  }
};

}  // namespace

const SensorKind& SonarKind() {
  static const Sonar kind;
  return kind;
}

}  // namespace sanet::sensors
