#include "sensors/odometry/odometry.h"

#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class WheelOdometry : public SensorInstance {
 public:
  WheelOdometry(OdometrySettings settings, Mount mount) : settings_(settings), mount_(mount), pose_(mount.start) {}

  std::optional<SensorReading> Read(const ReadContext& /*context*/) override {
    mount_.world.Settle();  // the step under way updates it (AfterPhysicsStep)
    return pose_;
  }

  void AfterPhysicsStep(double /*time*/) override {
    const physics::Vehicle& vehicle = *mount_.model.vehicle();
    const std::size_t n = vehicle.wheel_count();
    std::vector<double> delta(n);
    if (last_angles_.size() != n) last_angles_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const double a = vehicle.wheel_angle(i);
      delta[i] = a - last_angles_[i];
      last_angles_[i] = a;
    }
    Twist2D d = mount_.model.kinematics()->BodyTwist(delta);  // a displacement: the rates are increments
    if (settings_.noise > 0) {
      d.vx *= 1 + mount_.random.Gaussian(0, settings_.noise);
      d.vy *= 1 + mount_.random.Gaussian(0, settings_.noise);
      d.omega *= 1 + mount_.random.Gaussian(0, settings_.noise);
    }
    const Vec2 step = Rotate({d.vx, d.vy}, pose_.theta + d.omega / 2);
    pose_.x += step.x;
    pose_.y += step.y;
    pose_.theta = WrapAngle(pose_.theta + d.omega);
  }

 private:
  OdometrySettings settings_;
  Mount mount_;
  Pose2D pose_;
  std::vector<double> last_angles_;
};

class Odometry : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"odometry",
                                 "the pose integrated from the wheels' rotation, from the start pose",
                                 "Pose2D",
                                 "x, y in m, theta in rad",
                                 "nav_msgs/msg/Odometry",
                                 "odom"};
    return info;
  }
  std::any DefaultSettings(const robots::ModelSpec& /*model*/) const override { return OdometrySettings{}; }
  std::optional<std::string> Refuses(const robots::ModelSpec& model) const override {
    if (!robots::HasDrive(model))
      return "a " + std::string(robots::ModelName(model.kind)) + " has no wheels, so no odometry";
    return std::nullopt;
  }
  std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const override {
    return std::make_unique<WheelOdometry>(std::any_cast<OdometrySettings>(settings), mount);
  }
};

}  // namespace

const SensorKind& OdometryKind() {
  static const Odometry kind;
  return kind;
}

}  // namespace sanet::sensors
