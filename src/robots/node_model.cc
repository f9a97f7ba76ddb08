#include "robots/node_model.h"

#include <algorithm>
#include <cmath>

namespace sanet::robots {

const char* ModelSummary(ModelKind kind) {
  switch (kind) {
    case ModelKind::kMote:
      return "a sensor mote: a cube that rests until something pushes it; no drive";
    case ModelKind::kOmni3:
      return "Robertino-like omnidirectional robot with three omni wheels (holonomic), six IR sensors";
    case ModelKind::kDiffDrive:
      return "Pioneer-P2DX-like differential drive: two wheels and a passive caster, 180-degree laser";
  }
  return "?";
}

const char* ModelName(ModelKind kind) {
  switch (kind) {
    case ModelKind::kMote:
      return "mote";
    case ModelKind::kOmni3:
      return "omni3";
    case ModelKind::kDiffDrive:
      return "diffdrive";
  }
  return "?";
}

RangeSensorSpec DefaultIr(const ModelSpec& m) {
  const double radius = m.kind == ModelKind::kOmni3       ? m.omni3.body_radius
                        : m.kind == ModelKind::kDiffDrive ? m.diffdrive.body_width / 2
                                                          : m.mote.size / 2;
  return RangeSensorSpec::Ring(6, radius, 0.06, 0.8);
}

RangeSensorSpec DefaultLaser(const ModelSpec& m) {
  // The diffdrive chassis is centred a quarter of the caster offset behind the axle.
  const double front = m.kind == ModelKind::kDiffDrive
                           ? m.diffdrive.body_length / 2 - m.diffdrive.caster_offset / 4 + 0.01
                       : m.kind == ModelKind::kOmni3 ? m.omni3.body_radius
                                                     : m.mote.size / 2;
  return RangeSensorSpec::Fan(kPi, 181, front, 0.2, 8.0);
}

double FootprintRadius(const ModelSpec& m) {
  switch (m.kind) {
    case ModelKind::kOmni3:
      return m.omni3.body_radius;
    case ModelKind::kDiffDrive:  // the chassis sits a quarter of the caster offset behind the axle
      return std::hypot(m.diffdrive.body_length / 2, m.diffdrive.body_width / 2) + m.diffdrive.caster_offset / 4;
    case ModelKind::kMote:
      return m.mote.size * std::sqrt(0.5);
  }
  return 0;
}

double InscribedRadius(const ModelSpec& m) {
  switch (m.kind) {
    case ModelKind::kOmni3:
      return m.omni3.body_radius;
    case ModelKind::kDiffDrive:  // the chassis's centre is a quarter of the caster offset behind the pose's point
      return std::max(
          0.0, std::min(m.diffdrive.body_width / 2, m.diffdrive.body_length / 2 - m.diffdrive.caster_offset / 4));
    case ModelKind::kMote:
      return m.mote.size / 2;
  }
  return 0;
}

ModelSpec ModelSpec::Defaults(ModelKind kind) {
  ModelSpec s;
  s.kind = kind;
  switch (kind) {
    case ModelKind::kMote:
      break;
    case ModelKind::kOmni3:
      s.max_speed = 1.0;
      s.max_turn_rate = 3.0;
      s.sensors.ir = DefaultIr(s);
      break;
    case ModelKind::kDiffDrive:
      s.max_speed = 1.2;
      s.max_turn_rate = 3.0;
      s.sensors.laser = DefaultLaser(s);
      break;
  }
  return s;
}

NodeModel::NodeModel(physics::PhysicsWorld& world, const ModelSpec& spec, const Pose2D& pose, std::uint64_t seed,
                     const std::string& stream_prefix)
    : world_(world),
      spec_(spec),
      ground_truth_(spec.sensors.ground_truth_noise_position, spec.sensors.ground_truth_noise_angle,
                    RandomStream(seed, stream_prefix + "/ground_truth")) {
  switch (spec.kind) {
    case ModelKind::kMote:
      body_ = world.add_mote(spec.mote, pose);
      break;
    case ModelKind::kOmni3:
      vehicle_ = world.add_omni3(spec.omni3, pose);
      kinematics_ = std::make_unique<Omni3Kinematics>(spec.omni3.wheel_angles, spec.omni3.wheel_distance,
                                                      spec.omni3.wheel_radius);
      break;
    case ModelKind::kDiffDrive:
      vehicle_ = world.add_diffdrive(spec.diffdrive, pose);
      kinematics_ = std::make_unique<DiffDriveKinematics>(spec.diffdrive.axle_length, spec.diffdrive.wheel_radius);
      break;
  }
  if (vehicle_) {
    body_ = vehicle_;
    odometry_.emplace(*kinematics_, pose, spec.sensors.odometry_noise, RandomStream(seed, stream_prefix + "/odometry"));
  }
  if (spec.sensors.ir) ir_.emplace(*spec.sensors.ir, RandomStream(seed, stream_prefix + "/ir"));
  if (spec.sensors.laser) laser_.emplace(*spec.sensors.laser, RandomStream(seed, stream_prefix + "/laser"));
  if (spec.sensors.bearing) bearing_.emplace(*spec.sensors.bearing, RandomStream(seed, stream_prefix + "/bearing"));
}

bool Finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

Twist2D LimitDrive(const ModelSpec& model, const Twist2D& velocity) {
  Twist2D v = velocity;
  if (model.kind != ModelKind::kOmni3) v.vy = 0;  // only the omni wheels move sideways
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

void NodeModel::AfterPhysicsStep() {
  if (odometry_) odometry_->Update(*vehicle_);
}

std::optional<RangeScan> NodeModel::Ir() {
  if (!ir_) return std::nullopt;
  return ir_->Read(world_, *body_);
}

std::optional<RangeScan> NodeModel::Laser() {
  if (!laser_) return std::nullopt;
  return laser_->Read(world_, *body_);
}

std::optional<Pose2D> NodeModel::Odometry() const {
  if (!odometry_) return std::nullopt;
  world_.Settle();  // the step under way updates it (AfterPhysicsStep)
  return odometry_->pose();
}

Pose2D NodeModel::GroundTruth() { return ground_truth_.Read(body_->pose()); }

std::optional<BearingReading> NodeModel::Bearing(const Pose2D& target) {
  if (!bearing_) return std::nullopt;
  return bearing_->Read(body_->pose(), target);
}

}  // namespace sanet::robots
