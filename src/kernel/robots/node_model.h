// A node's physical side: its body in the physics world and its drive (motes have no drive).
// Its sensors are the sensors layer's (sensors/sensor_set.h), configured here by name.
#pragma once

#include <any>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "core/rgb.h"
#include "physics/physics_world.h"
#include "robots/kinematics.h"
#include "robots/robot_models.h"
#include "robots/urdf_robot.h"
#include "sanet/node.h"

namespace sanet::robots {

inline const char* ModelName(ModelKind kind) { return ModelOf(kind).Name(); }

// One sensor on a node: its registered kind (sensors/sensor_kinds.h) and that kind's settings,
// which only the kind's own files look into.
struct SensorConfig {
  std::string kind;
  std::any settings;
  // What it costs a node with `energy` (docs/energy.md#sensors): while the node is on, and per
  // reading taken.
  double power_w = 0;
  double energy_j = 0;
};
// A node's sensors by instance name: a kind's own name for its default instance ("laser"), any
// other name for more of a kind ("laser_rear").
using SensorConfigs = std::map<std::string, SensorConfig>;

// Where a body came from when a URDF file described it (scenario/urdf_body.h): what the
// effective scenario prints, so that the body can be read again without the file.
struct UrdfSource {
  std::string file;                 // as the scenario named it
  std::string text;                 // the file's content
  std::vector<std::string> wheels;  // the wheel joints: left, right
  std::string base_link;            // as given (empty: the URDF's root)
  // Every link's place, x forward and z up from the ground under the base link's origin (m).
  std::map<std::string, std::array<double, 3>> links;
  // The tf tree: the root link's pose in the same frame, and every joint from the root down.
  std::string root;
  UrdfPose root_pose;
  std::vector<UrdfJoint> joints;
  // Per wheel (as `wheels`): +1 where the joint's axis turns the wheel forward as the physics
  // turns it (its angle grows as it drives the body its way), -1 where it points the other way.
  std::vector<double> wheel_signs;
};

struct ModelSpec {
  ModelKind kind = ModelKind::kMote;
  std::shared_ptr<const UrdfSource> urdf;  // null: the body's keys alone
  physics::MoteSpec mote;
  physics::Omni3Spec omni3;
  physics::DiffDriveSpec diffdrive;
  double max_speed = 0;      // m/s, commands are clamped to it
  double max_turn_rate = 0;  // rad/s
  SensorConfigs sensors;
  std::optional<Rgb> color;  // what cameras see of its body; unset: the model's (sim/surroundings_of.h)

  // The model's body and drive defaults, without sensors (sensors::DefaultModel adds those).
  static ModelSpec Defaults(ModelKind kind) { return ModelOf(kind).Defaults(); }
  const RobotModel& model() const { return ModelOf(kind); }
};

// What the node's registered model says of it (robots/robot_model.h).
inline std::vector<std::string> DefaultSensorKinds(const ModelSpec& m) { return m.model().DefaultSensors(); }
inline double EdgeRadius(const ModelSpec& m) { return m.model().EdgeRadius(m); }
inline double FrontX(const ModelSpec& m) { return m.model().FrontX(m); }
inline double FootprintRadius(const ModelSpec& m) { return m.model().FootprintRadius(m); }
inline double InscribedRadius(const ModelSpec& m) { return m.model().InscribedRadius(m); }
inline bool HasDrive(const ModelSpec& m) { return m.model().HasDrive(); }
inline bool Holonomic(const ModelSpec& m) { return m.model().Holonomic(); }

// No NaN and no infinity among `values`: a command the motors can take.
bool Finite(const std::vector<double>& values);

// The model's drive limits, the one rule every mode applies (the simulated node, an agent, a ROS 2
// robot): no sideways motion for a robot that cannot make it, the speed over the ground scaled
// down to max_speed (keeping the direction), the turn rate clamped to max_turn_rate.
Twist2D LimitDrive(const ModelSpec& model, const Twist2D& velocity);

class NodeModel {
 public:
  NodeModel(physics::PhysicsWorld& world, const ModelSpec& spec, const Pose2D& pose);

  const ModelSpec& spec() const { return spec_; }
  const physics::Body& body() const { return *body_; }
  bool mobile() const { return vehicle_ != nullptr; }
  bool holonomic() const { return kinematics_ && kinematics_->holonomic(); }
  // The drive, for sensors that read it (odometry): null on a mote.
  const physics::Vehicle* vehicle() const { return vehicle_; }
  const Kinematics* kinematics() const { return kinematics_.get(); }

  // Actuators: clamp and hand the wheel speeds to the motors. False on a mote.
  bool Drive(const Twist2D& velocity);
  bool SetWheelSpeeds(const std::vector<double>& rad_per_s);

 private:
  ModelSpec spec_;
  physics::Body* body_ = nullptr;
  physics::Vehicle* vehicle_ = nullptr;
  std::unique_ptr<Kinematics> kinematics_;
};

}  // namespace sanet::robots
