// Sensor models. Each reads the physical world (or the robot's own wheels) and adds Gaussian
// noise from its own random stream when its noise is non-zero.
#pragma once

#include <optional>
#include <vector>

#include "core/random_stream.h"
#include "physics/physics_world.h"
#include "robots/kinematics.h"
#include "sanet/node.h"

namespace sanet::robots {

// A fan of rays from a mount on the robot: the IR ring and the planar laser both.
struct RangeSensorSpec {
  std::vector<double> angles;  // rad, robot frame, one per beam
  double max_range = 1.0;      // m
  double mount_x = 0;          // m, robot frame, where the rays start (before `mount_radius`)
  double mount_radius = 0;     // m, rays start this far out along their own direction
  double mount_height = 0.1;   // m above the ground
  double noise = 0;            // m, standard deviation of each range

  static RangeSensorSpec Ring(int count, double radius, double height, double max_range);
  static RangeSensorSpec Fan(double fov, int beams, double mount_x, double height, double max_range);
};

class RangeSensor {
 public:
  RangeSensor(RangeSensorSpec spec, RandomStream noise) : spec_(std::move(spec)), rng_(noise) {}
  RangeScan Read(const physics::PhysicsWorld& world, const physics::Body& self);
  const RangeSensorSpec& spec() const { return spec_; }

 private:
  RangeSensorSpec spec_;
  RandomStream rng_;
};

// Pose integrated from wheel rotation, starting at the robot's initial pose.
class Odometry {
 public:
  // `noise`: relative standard deviation applied to every increment of travel and turn.
  Odometry(const Kinematics& kinematics, Pose2D start, double noise, RandomStream rng)
      : kinematics_(kinematics), pose_(start), noise_(noise), rng_(rng) {}
  void Update(const physics::Vehicle& vehicle);  // after each physics step
  const Pose2D& pose() const { return pose_; }

 private:
  const Kinematics& kinematics_;
  Pose2D pose_;
  double noise_;
  RandomStream rng_;
  std::vector<double> last_angles_;
};

struct BearingSpec {
  double range = 0;           // m; beyond it the sensor answers nothing
  double noise_distance = 0;  // m
  double noise_angle = 0;     // rad
};

class BearingSensor {
 public:
  BearingSensor(BearingSpec spec, RandomStream rng) : spec_(spec), rng_(rng) {}
  std::optional<BearingReading> Read(const Pose2D& self, const Pose2D& target);

 private:
  BearingSpec spec_;
  RandomStream rng_;
};

class GroundTruthSensor {
 public:
  GroundTruthSensor(double noise_position, double noise_angle, RandomStream rng)
      : noise_position_(noise_position), noise_angle_(noise_angle), rng_(rng) {}
  Pose2D Read(const Pose2D& truth);

 private:
  double noise_position_, noise_angle_;
  RandomStream rng_;
};

}  // namespace sanet::robots
