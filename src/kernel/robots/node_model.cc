#include "robots/node_model.h"

#include <algorithm>
#include <cmath>

namespace sanet::robots {

NodeModel::NodeModel(physics::PhysicsWorld& world, const ModelSpec& spec, const Pose2D& pose) : spec_(spec) {
  body_ = spec.model().Build(world, spec, pose, &vehicle_);
  kinematics_ = spec.model().MakeKinematics(spec);
}

bool Finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

Twist2D LimitDrive(const ModelSpec& model, const Twist2D& velocity) {
  Twist2D v = velocity;
  if (!Holonomic(model)) v.vy = 0;  // only a holonomic drive moves sideways
  const double speed = std::hypot(v.vx, v.vy);
  if (speed > model.max_speed) {
    v.vx *= model.max_speed / speed;
    v.vy *= model.max_speed / speed;
  }
  v.omega = std::clamp(v.omega, -model.max_turn_rate, model.max_turn_rate);
  return v;
}

bool NodeModel::Drive(const Twist2D& velocity) {
  if (!vehicle_ || !Finite({velocity.vx, velocity.vy, velocity.omega})) return false;
  return SetWheelSpeeds(kinematics_->WheelSpeeds(LimitDrive(spec_, velocity)));
}

bool NodeModel::SetWheelSpeeds(const std::vector<double>& rad_per_s) {
  if (!vehicle_ || rad_per_s.size() != vehicle_->wheel_count() || !Finite(rad_per_s)) return false;
  for (std::size_t i = 0; i < rad_per_s.size(); ++i) vehicle_->set_wheel_speed(i, rad_per_s[i]);
  return true;
}

}  // namespace sanet::robots
