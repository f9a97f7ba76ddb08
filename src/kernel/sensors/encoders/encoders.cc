// The encoders' kernel part: the vehicle's wheel angles, counted in ticks, and their rates.
#include "sensors/encoders/encoders.h"

#include <cmath>

#include "sensors/sampling_sensor.h"
#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

// Sampled at its rate, as a motor controller counts its wheels' ticks: each sample's speed is the
// mean over the period before it.
class WheelEncoders : public SamplingSensor {
 public:
  WheelEncoders(EncodersSettings settings, Mount mount)
      : SamplingSensor(settings.rate, mount.world), settings_(std::move(settings)), mount_(mount) {}

 private:
  SensorReading Sample(double period) override {
    const physics::Vehicle& vehicle = *mount_.model.vehicle();
    const std::size_t n = vehicle.wheel_count();
    const bool first = last_angles_.size() != n;
    if (first) last_angles_.assign(n, 0.0);
    JointStatesReading r;
    r.names = settings_.names;
    r.names.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double exact = vehicle.wheel_angle(i);
      r.angles.push_back(settings_.resolution > 0 ? std::floor(exact / settings_.resolution) * settings_.resolution
                                                  : exact);
      double speed = first ? 0 : (exact - last_angles_[i]) / period;
      if (settings_.noise > 0) speed = mount_.random.Gaussian(speed, settings_.noise);
      r.speeds.push_back(speed);
      last_angles_[i] = exact;
    }
    return r;
  }

  EncodersSettings settings_;
  Mount mount_;
  std::vector<double> last_angles_;
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
  bool SamplesOnItsOwn() const override { return true; }
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
