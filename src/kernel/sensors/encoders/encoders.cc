// The encoders' kernel part: the vehicle's wheel angles, counted in ticks, and their rates.
#include "sensors/encoders/encoders.h"

#include <cmath>

#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class WheelEncoders : public SensorInstance {
 public:
  WheelEncoders(EncodersSettings settings, Mount mount) : settings_(std::move(settings)), mount_(mount) {}

  std::optional<SensorReading> Read(const ReadContext& context) override {
    mount_.world.Settle();  // the step under way turns the wheels
    const physics::Vehicle& vehicle = *mount_.model.vehicle();
    const std::size_t n = vehicle.wheel_count();
    if (last_angles_.size() != n) last_angles_.assign(n, 0.0);
    JointStatesReading r;
    r.names = settings_.names;
    r.names.resize(n);
    const double dt = context.time - last_time_;
    for (std::size_t i = 0; i < n; ++i) {
      const double exact = vehicle.wheel_angle(i);
      r.angles.push_back(settings_.resolution > 0 ? std::floor(exact / settings_.resolution) * settings_.resolution
                                                  : exact);
      double speed = dt > 0 ? (exact - last_angles_[i]) / dt : last_speeds_.size() == n ? last_speeds_[i] : 0;
      if (settings_.noise > 0) speed = mount_.random.Gaussian(speed, settings_.noise);
      r.speeds.push_back(speed);
      if (dt > 0) last_angles_[i] = exact;
    }
    if (dt > 0) last_time_ = context.time, last_speeds_ = r.speeds;
    return r;
  }

 private:
  EncodersSettings settings_;
  Mount mount_;
  std::vector<double> last_angles_, last_speeds_;
  double last_time_ = 0;
};

class Encoders : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"encoders",
                                 "each wheel's angle and speed, as the physics turns it",
                                 "JointStatesReading",
                                 "per wheel: its joint's name, angle in rad (from the start), speed in rad/s",
                                 "sensor_msgs/msg/JointState",
                                 "joint_states"};
    return info;
  }
  std::any DefaultSettings(const robots::ModelSpec& model) const override {
    EncodersSettings s;
    if (model.urdf)
      s.names = model.urdf->wheels;
    else if (model.kind == robots::ModelKind::kDiffDrive)
      s.names = {"left_wheel_joint", "right_wheel_joint"};
    else
      s.names = {"wheel_0_joint", "wheel_1_joint", "wheel_2_joint"};
    return s;
  }
  std::optional<std::string> Refuses(const robots::ModelSpec& model) const override {
    if (!robots::HasDrive(model))
      return "a " + std::string(robots::ModelName(model.kind)) + " has no wheels, so no encoders";
    return std::nullopt;
  }
  std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const override {
    return std::make_unique<WheelEncoders>(std::any_cast<const EncodersSettings&>(settings), mount);
  }
};

}  // namespace

const SensorKind& EncodersKind() {
  static const Encoders kind;
  return kind;
}

}  // namespace sanet::sensors
