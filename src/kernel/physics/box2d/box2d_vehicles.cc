// The robots of the 2D world and how their wheels drive them. Body frames: x forward, y left;
// the body's origin is the robot's reference point; its centre of mass may lie elsewhere.
#include <algorithm>
#include <cmath>

#include "physics/box2d/box2d_world.h"

namespace sanet::physics::box2d {
namespace {

constexpr int kWheelIterations = 4;  // passes over a robot's wheels per step (sequential impulses)

b2Vec2 Perpendicular(b2Vec2 v) { return b2Vec2(-v.y, v.x); }

// Sets mass, centre of mass (body frame) and rotational inertia about the centre of mass.
void SetMass(b2Body* body, double mass, b2Vec2 centre, double inertia_about_centre) {
  b2MassData data;
  data.mass = static_cast<float>(mass);
  data.center = centre;
  data.I = static_cast<float>(inertia_about_centre + mass * b2Dot(centre, centre));  // Box2D: about the origin
  body->SetMassData(&data);
}

}  // namespace

Box2dVehicle::Box2dVehicle(b2Body* body, double height, std::vector<Wheel> wheels)
    : Box2dBody(body, height), wheels_(std::move(wheels)), impulses_(wheels_.size()) {}

void Box2dVehicle::set_wheel_speed(std::size_t wheel, double rad_per_s) {
  wheels_.at(wheel).target = rad_per_s;
  if (rad_per_s != 0) body_->SetAwake(true);
}

// Each wheel's contact point is driven, along its rolling direction, towards the rim speed its
// motor holds and, along its axle, towards standing still; each impulse is bounded by what the
// motor and the friction there can give in one step. The passes solve the wheels together, as
// Box2D solves its contacts: the accumulated impulse of a wheel is what is bounded.
void Box2dVehicle::DriveWheels(double dt) {
  const double mass = body_->GetMass();
  const b2Vec2 centre = body_->GetWorldCenter();
  const double inertia = body_->GetInertia() - mass * b2Dot(body_->GetLocalCenter(), body_->GetLocalCenter());
  std::fill(impulses_.begin(), impulses_.end(), std::array<double, 2>{0, 0});
  for (int pass = 0; pass < kWheelIterations; ++pass)
    for (std::size_t i = 0; i < wheels_.size(); ++i) {
      const Wheel& w = wheels_[i];
      const b2Vec2 at = body_->GetWorldPoint(w.contact);
      const b2Vec2 rolling = body_->GetWorldVector(w.rolling);
      const b2Vec2 arm = at - centre;
      const b2Vec2 directions[2] = {rolling, Perpendicular(rolling)};
      const double wanted[2] = {w.target * w.radius, 0};
      const double limits[2] = {std::min(w.max_force, w.grip * w.load) * dt, w.side * w.load * dt};
      for (int k = 0; k < 2; ++k) {
        const double speed = b2Dot(body_->GetLinearVelocityFromWorldPoint(at), directions[k]);
        const double lever = b2Cross(arm, directions[k]);
        const double effective_mass = 1.0 / (1.0 / mass + lever * lever / inertia);
        double& accumulated = impulses_[i][k];
        const double before = accumulated;
        accumulated = std::clamp(before + effective_mass * (wanted[k] - speed), -limits[k], limits[k]);
        const double after = accumulated;
        body_->ApplyLinearImpulse(static_cast<float>(after - before) * directions[k], at, false);
      }
    }
  TallyMotorWork();
}

// A wheel here is its contact point: its motor's work in the step is the impulse it gave along
// the rolling direction times the speed the point then has there (force times velocity), where
// that is positive. The impulses along the axle are friction's, which does no motor's work.
void Box2dVehicle::TallyMotorWork() {
  for (std::size_t i = 0; i < wheels_.size(); ++i) {
    const Wheel& w = wheels_[i];
    const b2Vec2 at = body_->GetWorldPoint(w.contact);
    const double speed = b2Dot(body_->GetLinearVelocityFromWorldPoint(at), body_->GetWorldVector(w.rolling));
    tally_.motor_work_j += std::max(0.0, impulses_[i][0] * speed);
  }
}

void Box2dVehicle::RollWheels(double dt) {
  for (Wheel& w : wheels_) {
    const b2Vec2 v = body_->GetLinearVelocityFromLocalPoint(w.contact);
    const double rolled = b2Dot(v, body_->GetWorldVector(w.rolling)) * dt;
    w.angle += rolled / w.radius;
    tally_.weight_rolled_j += w.load * std::abs(rolled);
  }
}

// A disc of the lower cylinder's radius; three omni wheels on radial axles. A positive speed
// moves a wheel's rim along the tangent (-sin a, cos a) at the top (robots::Omni3Kinematics),
// so at the ground, where it pushes, the robot is carried the other way; each wheel grips along
// the tangent and slips along its axle.
Vehicle* Box2dWorld::add_omni3(const Omni3Spec& spec, const Pose2D& pose) {
  b2Body* body = MakeBody(b2_dynamicBody, pose);
  b2CircleShape disc;
  disc.m_radius = static_cast<float>(spec.body_radius);
  body->CreateFixture(&disc, 0);
  const double mass = spec.body_mass + 3 * spec.wheel_mass;
  const double body_izz =
      spec.body_inertia[2] > 0 ? spec.body_inertia[2] : 0.5 * spec.body_mass * spec.body_radius * spec.body_radius;
  SetMass(body, mass, b2Vec2(0, 0), body_izz + 3 * spec.wheel_mass * spec.wheel_distance * spec.wheel_distance);
  std::vector<Wheel> wheels;
  for (double a : spec.wheel_angles) {
    Wheel w;
    w.contact = b2Vec2(static_cast<float>(spec.wheel_distance * std::cos(a)),
                       static_cast<float>(spec.wheel_distance * std::sin(a)));
    w.rolling = b2Vec2(static_cast<float>(std::sin(a)), static_cast<float>(-std::cos(a)));
    w.radius = spec.wheel_radius;
    w.max_force = spec.max_wheel_torque / spec.wheel_radius;
    w.grip = spec.grip_friction;
    w.side = spec.slip_friction;
    w.load = mass * settings_.gravity / 3;
    wheels.push_back(w);
  }
  return AddVehicle(body, spec.ground_clearance + spec.body_height / 2, std::move(wheels));
}

// The chassis box, its centre of mass between the axle and the caster (as in 3D, so the
// wheels carry three quarters of the weight); two drive wheels, wheel 0 on the left. The
// caster is frictionless and carries the rest.
Vehicle* Box2dWorld::add_diffdrive(const DiffDriveSpec& spec, const Pose2D& pose) {
  const double com_behind_axle = spec.caster_offset / 4;
  b2Body* body = MakeBody(b2_dynamicBody, pose);
  b2PolygonShape box;
  box.SetAsBox(static_cast<float>(spec.body_length / 2), static_cast<float>(spec.body_width / 2),
               b2Vec2(static_cast<float>(-com_behind_axle), 0), 0);
  body->CreateFixture(&box, 0);
  const double mass = spec.body_mass + 2 * spec.wheel_mass;
  const double half_axle = spec.axle_length / 2;
  const double body_izz =
      spec.body_inertia[2] > 0
          ? spec.body_inertia[2]
          : spec.body_mass * (spec.body_length * spec.body_length + spec.body_width * spec.body_width) / 12;
  SetMass(body, mass, b2Vec2(static_cast<float>(-com_behind_axle), 0),
          body_izz + 2 * spec.wheel_mass * half_axle * half_axle);
  const double on_axle = 1 - com_behind_axle / spec.caster_offset;
  const double grip = std::min(spec.wheel_friction, settings_.ground_friction);
  std::vector<Wheel> wheels;
  for (double side : {1.0, -1.0}) {
    Wheel w;
    w.contact = b2Vec2(0, static_cast<float>(side * half_axle));
    w.rolling = b2Vec2(1, 0);
    w.radius = spec.wheel_radius;
    w.max_force = spec.max_wheel_torque / spec.wheel_radius;
    w.grip = grip;
    w.side = grip;
    w.load = mass * settings_.gravity * on_axle / 2;
    wheels.push_back(w);
  }
  return AddVehicle(body, spec.ground_clearance + spec.body_height / 2, std::move(wheels));
}

}  // namespace sanet::physics::box2d
