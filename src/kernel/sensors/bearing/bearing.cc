#include "sensors/bearing/bearing.h"

#include <algorithm>

#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class RangeAndBearing : public SensorInstance {
 public:
  RangeAndBearing(BearingSettings settings, Mount mount) : settings_(settings), mount_(mount) {}

  // Aimed at one node: that node if it is in range. Otherwise every other node in range, in
  // node order (each draws its noise in that order).
  std::optional<SensorReading> Read(const ReadContext& context) override {
    BearingsReading out;
    const Pose2D self = mount_.model.body().pose();
    for (NodeId other = 0; other < context.node_count; ++other) {
      if (other == context.self || (context.target && other != *context.target)) continue;
      if (const auto b = Towards(self, context.true_pose(other))) out.in_range.push_back({other, *b});
    }
    return out;
  }

 private:
  std::optional<BearingReading> Towards(const Pose2D& self, const Pose2D& target) {
    const Vec2 offset = target.position() - self.position();
    const double distance = Norm(offset);
    if (distance > settings_.range) return std::nullopt;
    BearingReading r{distance, WrapAngle(std::atan2(offset.y, offset.x) - self.theta)};
    RandomStream& random = mount_.random;
    if (settings_.noise_distance > 0) r.distance = std::max(0.0, random.Gaussian(r.distance, settings_.noise_distance));
    if (settings_.noise_angle > 0) r.bearing = WrapAngle(random.Gaussian(r.bearing, settings_.noise_angle));
    return r;
  }

  BearingSettings settings_;
  Mount mount_;
};

class Bearing : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"bearing",
                                 "distance and direction to every other node within range (Node::Bearing(target) "
                                 "reads one node)",
                                 "BearingsReading",
                                 "distance in m, bearing in rad, robot frame",
                                 "",
                                 ""};
    return info;
  }
  std::any DefaultSettings(const robots::ModelSpec& /*model*/) const override { return BearingSettings{}; }
  std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const override {
    return std::make_unique<RangeAndBearing>(std::any_cast<BearingSettings>(settings), mount);
  }
};

}  // namespace

const SensorKind& BearingKind() {
  static const Bearing kind;
  return kind;
}

}  // namespace sanet::sensors
