// Box2D implementation of PhysicsWorld: the world seen from above, for swarms. Internal to
// physics/: nothing outside includes it.
//
// A robot is one rigid body in the plane whose origin is its reference point (the centre
// between its wheels). Its wheels are not bodies: each is a contact point that the step drives
// with impulses, as a motor holding a velocity target would (limited by the motor's force and
// by the wheel's grip, friction times the wheel's share of the robot's weight), and that resists
// sliding along its axle (a drive wheel grips; an omni wheel's rollers slip). Motes, walls and
// boxes are static bodies; collisions between all of them are Box2D's. Everything is a prism
// of unlimited height: a ray at any height hits a mote.
//
// Bodies at rest cost nothing: Box2D puts a robot to sleep once it has been still for half a
// second, and the wheels of a sleeping robot are not driven until a command wakes it.
#pragma once

#include <box2d/box2d.h>

#include <array>
#include <memory>
#include <vector>

#include "physics/physics_world.h"

namespace sanet::physics::box2d {

// A wheel as the ground sees it, in the body frame.
struct Wheel {
  b2Vec2 contact;        // m, from the reference point
  b2Vec2 rolling;        // unit: where a positive speed moves the rim
  double radius = 0;     // m
  double max_force = 0;  // N at the rim: the motor's torque over the radius
  double grip = 0;       // friction coefficient along the rolling direction
  double side = 0;       // friction coefficient along the axle
  double load = 0;       // N: the wheel's share of the robot's weight
  double target = 0;     // rad/s, the motor's velocity target
  double angle = 0;      // rad, unwrapped rotation since creation
};

class Box2dBody : public virtual Body {
 public:
  Box2dBody(b2Body* body, double height) : body_(body), height_(height) {}
  Pose2D pose() const override;
  Vec3 position3() const override;
  Twist2D velocity() const override;
  bool awake() const override { return body_->GetType() != b2_staticBody && body_->IsAwake(); }
  b2Body* body() const { return body_; }

 protected:
  b2Body* body_;
  double height_;  // m: what position3 reports as z (the body's centre above the ground)
};

class Box2dVehicle : public Box2dBody, public Vehicle {
 public:
  Box2dVehicle(b2Body* body, double height, std::vector<Wheel> wheels);
  std::size_t wheel_count() const override { return wheels_.size(); }
  void set_wheel_speed(std::size_t wheel, double rad_per_s) override;
  double wheel_angle(std::size_t wheel) const override { return wheels_.at(wheel).angle; }
  DriveTally drive_tally() const override { return tally_; }
  // Before the world's step: drives the wheels' contact points towards their targets.
  void DriveWheels(double dt);
  // After it: turns the wheels as far as their contact points rolled.
  void RollWheels(double dt);

 private:
  void TallyMotorWork();  // after DriveWheels
  std::vector<Wheel> wheels_;
  std::vector<std::array<double, 2>> impulses_;  // per wheel, accumulated in this step: rolling, axle
  DriveTally tally_;
};

class Box2dWorld : public PhysicsWorld, private b2ContactListener {
 public:
  explicit Box2dWorld(const WorldSettings& settings);

  void add_static_box(const StaticBox& box) override;
  Vehicle* add_omni3(const Omni3Spec& spec, const Pose2D& pose) override;
  Vehicle* add_diffdrive(const DiffDriveSpec& spec, const Pose2D& pose) override;
  Body* add_mote(const MoteSpec& spec, const Pose2D& pose) override;
  double cast_ray(const Vec3& origin, const Vec3& direction, double max_range, const Body* ignore) const override;
  std::vector<double> cast_rays(const std::vector<Ray>& rays, double max_range, const Body* ignore) const override;
  void step(double dt) override;
  std::size_t awake_body_count() const override;
  double gravity() const override { return settings_.gravity; }

 private:
  b2Body* MakeBody(b2BodyType type, const Pose2D& pose);
  Vehicle* AddVehicle(b2Body* body, double height, std::vector<Wheel> wheels);
  // Contacts take the smaller friction of the two, as in the 3D world (Box2D's own mix is the
  // geometric mean).
  void BeginContact(b2Contact* contact) override;

  WorldSettings settings_;
  b2World world_;
  std::vector<std::unique_ptr<Box2dVehicle>> vehicles_;
  std::vector<std::unique_ptr<Box2dBody>> motes_;
};

}  // namespace sanet::physics::box2d
