// A kind of node body as the kernel knows it: a registered model (mote, omni3, diffdrive), one
// folder each under src/models/, registered once in robots/robot_models.h. A model gives its
// body and drive defaults and limits, the sensors it carries, how it sits in the world (for
// placement and for sensors' mounts), its wheels' kinematics, how it is built in the physics
// world, and what front ends say of it (its USARSim steering, its shape for markers). The drive
// limits themselves are one rule for every model (robots::LimitDrive).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "physics/physics_world.h"
#include "robots/kinematics.h"

namespace sanet::robots {

struct ModelSpec;

// A body's outline for drawing it: a box (length along x, width) or a vertical cylinder.
struct BodyShape {
  bool box = true;
  double length = 0, width = 0, radius = 0;
  double height = 0;  // m
  double base = 0;    // m from the ground to its bottom
};

class RobotModel {
 public:
  virtual ~RobotModel() = default;
  virtual const char* Name() const = 0;
  virtual const char* Summary() const = 0;  // what it is, in a line (`sanet list`)
  // Its body, drive and limits as a scenario gets them without `body` keys (no sensors).
  virtual ModelSpec Defaults() const = 0;
  virtual std::vector<std::string> DefaultSensors() const = 0;  // kinds it carries by default
  virtual bool HasDrive() const { return true; }
  virtual bool Holonomic() const { return false; }  // it honours a sideways velocity (vy)
  // How it sits on the ground: the circle about its pose's point that holds the whole body, the
  // largest circle inside it, its edge (a ring of sensors) and its front (a forward sensor).
  virtual double FootprintRadius(const ModelSpec& spec) const = 0;
  virtual double InscribedRadius(const ModelSpec& spec) const = 0;
  virtual double EdgeRadius(const ModelSpec& spec) const = 0;
  virtual double FrontX(const ModelSpec& spec) const = 0;
  virtual BodyShape Shape(const ModelSpec& spec) const = 0;
  // Its wheels: kinematics (null without a drive), radius, and the distance USARSim's GEO calls
  // the wheel separation.
  virtual std::unique_ptr<Kinematics> MakeKinematics(const ModelSpec& /*spec*/) const { return nullptr; }
  virtual double WheelRadius(const ModelSpec& /*spec*/) const { return 0; }
  virtual double WheelSeparation(const ModelSpec& /*spec*/) const { return 0; }
  // USARSim's name for its steering ("SkidSteered": DRIVE {Left} {Right}; "OmniDrive"); "" for a
  // body without a drive.
  virtual const char* UsarsimSteering() const { return ""; }
  // Its body in `world` at `pose`; `vehicle` set for a model with a drive.
  virtual physics::Body* Build(physics::PhysicsWorld& world, const ModelSpec& spec, const Pose2D& pose,
                               physics::Vehicle** vehicle) const = 0;
};

}  // namespace sanet::robots
