#include "sensors/ground_truth/ground_truth.h"

#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class TruePose : public SensorInstance {
 public:
  TruePose(GroundTruthSettings settings, Mount mount) : settings_(settings), mount_(mount) {}

  std::optional<SensorReading> Read(const ReadContext& /*context*/) override {
    const Pose2D truth = mount_.model.body().pose();
    if (settings_.noise_position <= 0 && settings_.noise_angle <= 0) return truth;
    RandomStream& r = mount_.random;
    return Pose2D{r.Gaussian(truth.x, settings_.noise_position), r.Gaussian(truth.y, settings_.noise_position),
                  WrapAngle(r.Gaussian(truth.theta, settings_.noise_angle))};
  }

 private:
  GroundTruthSettings settings_;
  Mount mount_;
};

class GroundTruth : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"ground_truth",
                                 "the node's true pose, optionally with noise",
                                 "Pose2D",
                                 "x, y in m, theta in rad",
                                 "nav_msgs/msg/Odometry",
                                 "ground_truth"};
    return info;
  }
  std::any DefaultSettings(const robots::ModelSpec& /*model*/) const override { return GroundTruthSettings{}; }
  bool Removable() const override { return false; }
  std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const override {
    return std::make_unique<TruePose>(std::any_cast<GroundTruthSettings>(settings), mount);
  }
};

}  // namespace

const SensorKind& GroundTruthKind() {
  static const GroundTruth kind;
  return kind;
}

}  // namespace sanet::sensors
