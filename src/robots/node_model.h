// A node's physical side: its body in the physics world, its drive and its sensors. Motes have
// a body and sensors but no drive.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "physics/physics_world.h"
#include "robots/kinematics.h"
#include "robots/sensors.h"

namespace sanet::robots {

enum class ModelKind { kMote, kOmni3, kDiffDrive };

const char* ModelName(ModelKind kind);
// What the model is, in a line (`sanet list`, the scenario reference).
const char* ModelSummary(ModelKind kind);
constexpr ModelKind kAllModels[] = {ModelKind::kMote, ModelKind::kOmni3, ModelKind::kDiffDrive};

struct SensorSuite {
  std::optional<RangeSensorSpec> ir;
  std::optional<RangeSensorSpec> laser;
  std::optional<BearingSpec> bearing;
  double odometry_noise = 0;               // relative, per increment
  double ground_truth_noise_position = 0;  // m
  double ground_truth_noise_angle = 0;     // rad
};

struct ModelSpec {
  ModelKind kind = ModelKind::kMote;
  physics::MoteSpec mote;
  physics::Omni3Spec omni3;
  physics::DiffDriveSpec diffdrive;
  double max_speed = 0;      // m/s, commands are clamped to it
  double max_turn_rate = 0;  // rad/s
  SensorSuite sensors;

  // The model's defaults: omni3 carries six IR sensors, diffdrive a 180-degree laser.
  static ModelSpec Defaults(ModelKind kind);
};

// The IR ring and the laser a model carries by default, placed on its body: the ring at the
// body's edge, 6 cm up (low enough to see motes); the laser at the front, 20 cm up.
RangeSensorSpec DefaultIr(const ModelSpec& model);
RangeSensorSpec DefaultLaser(const ModelSpec& model);
// The radius of the circle about the pose's point that holds the whole body, seen from above.
double FootprintRadius(const ModelSpec& model);
// The radius of the largest circle about the pose's point that lies inside the body, seen from
// above: two bodies whose inscribed circles meet certainly overlap.
double InscribedRadius(const ModelSpec& model);

// No NaN and no infinity among `values`: a command the motors can take.
bool Finite(const std::vector<double>& values);

// The model's drive limits, the one rule every mode applies (the simulated node, an agent, a ROS 2
// robot): no sideways motion for a robot that cannot make it, the speed over the ground scaled
// down to max_speed (keeping the direction), the turn rate clamped to max_turn_rate.
Twist2D LimitDrive(const ModelSpec& model, const Twist2D& velocity);

class NodeModel {
 public:
  // `seed` and `stream_prefix` give each sensor its own random stream.
  NodeModel(physics::PhysicsWorld& world, const ModelSpec& spec, const Pose2D& pose, std::uint64_t seed,
            const std::string& stream_prefix);

  const ModelSpec& spec() const { return spec_; }
  const physics::Body& body() const { return *body_; }
  bool mobile() const { return vehicle_ != nullptr; }
  bool holonomic() const { return kinematics_ && kinematics_->holonomic(); }

  // Actuators: clamp and hand the wheel speeds to the motors. False on a mote.
  bool Drive(const Twist2D& velocity);
  bool SetWheelSpeeds(const std::vector<double>& rad_per_s);

  // Called after every physics step.
  void AfterPhysicsStep();

  std::optional<RangeScan> Ir();
  std::optional<RangeScan> Laser();
  std::optional<Pose2D> Odometry() const;
  Pose2D GroundTruth();
  std::optional<BearingReading> Bearing(const Pose2D& target);

 private:
  physics::PhysicsWorld& world_;
  ModelSpec spec_;
  physics::Body* body_ = nullptr;
  physics::Vehicle* vehicle_ = nullptr;
  std::unique_ptr<Kinematics> kinematics_;
  std::optional<RangeSensor> ir_, laser_;
  std::optional<BearingSensor> bearing_;
  std::optional<robots::Odometry> odometry_;
  GroundTruthSensor ground_truth_;
};

}  // namespace sanet::robots
