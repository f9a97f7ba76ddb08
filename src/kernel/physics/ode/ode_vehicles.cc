// Builders of the wheeled robots. Body frames: x forward, y left, z up; a vehicle's body
// origin is its centre of mass (ODE requires it), its reference point the centre between its
// wheels on which poses are reported.
#include <cmath>

#include "physics/ode/ode_world.h"

namespace sanet::physics::ode {
namespace {

// A body's principal moments (kg m²) in place of its shape's, when given (all three > 0).
void SetMoments(dMass& mass, const std::array<double, 3>& moments) {
  if (moments[0] <= 0 || moments[1] <= 0 || moments[2] <= 0) return;
  dMassSetParameters(&mass, mass.mass, 0, 0, 0, moments[0], moments[1], moments[2], 0, 0, 0);
}

// Places a freshly made body at `local` (in the frame of a robot standing at `pose`, z from the
// ground) with the robot's yaw.
void Place(dBodyID body, const Pose2D& pose, Vec3 local) {
  const Vec2 p = ToWorld(pose, {local.x, local.y});
  dBodySetPosition(body, p.x, p.y, local.z);
  dMatrix3 r;
  dRFromAxisAndAngle(r, 0, 0, 1, pose.theta);
  dBodySetRotation(body, r);
}

dGeomID Attach(dGeomID geom, dBodyID body, Vec3 offset) {
  dGeomSetBody(geom, body);
  dGeomSetOffsetPosition(geom, offset.x, offset.y, offset.z);
  return geom;
}

}  // namespace

Vehicle* OdeWorld::add_omni3(const Omni3Spec& spec, const Pose2D& pose) {
  const double z_body = spec.ground_clearance + spec.body_height / 2;
  dBodyID chassis = dBodyCreate(world_);
  Place(chassis, pose, {0, 0, z_body});
  dMass mass;
  dMassSetCylinderTotal(&mass, spec.body_mass, 3, spec.body_radius, spec.body_height);
  SetMoments(mass, spec.body_inertia);
  dBodySetMass(chassis, &mass);
  vehicles_.push_back(std::make_unique<OdeVehicle>(chassis, Vec3{0, 0, 0}));
  OdeVehicle* robot = vehicles_.back().get();

  const double half = spec.body_height / 2;
  GeomInfo* chassis_info = make_info({Part::kChassis, robot, nullptr, kChassisFriction, 0});
  dGeomSetData(Attach(dCreateCylinder(moving_, spec.body_radius, half), chassis, {0, 0, -half / 2}), chassis_info);
  dGeomSetData(Attach(dCreateCylinder(moving_, 0.8 * spec.body_radius, half), chassis, {0, 0, half / 2}), chassis_info);

  for (double angle : spec.wheel_angles) {
    const Vec3 local{spec.wheel_distance * std::cos(angle), spec.wheel_distance * std::sin(angle), spec.wheel_radius};
    dBodyID wheel = dBodyCreate(world_);
    Place(wheel, pose, local);
    dMassSetSphereTotal(&mass, spec.wheel_mass, spec.wheel_radius);
    dBodySetMass(wheel, &mass);
    dJointID hinge = dJointCreateHinge(world_, nullptr);
    dJointAttach(hinge, wheel, chassis);  // the hinge rate is then the wheel's spin
    const Vec2 anchor = ToWorld(pose, {local.x, local.y});
    dJointSetHingeAnchor(hinge, anchor.x, anchor.y, local.z);
    // Radial axis: the wheel rolls tangentially, around the robot's centre.
    dJointSetHingeAxis(hinge, std::cos(angle + pose.theta), std::sin(angle + pose.theta), 0);
    dGeomID g = dCreateSphere(moving_, spec.wheel_radius);
    dGeomSetBody(g, wheel);
    dGeomSetData(g, make_info({Part::kOmniWheel, robot, hinge, spec.grip_friction, spec.slip_friction}));
    const double weight = (spec.body_mass + 3 * spec.wheel_mass) * settings_.gravity / 3;
    robot->add_wheel(wheel, hinge, spec.max_wheel_torque, spec.wheel_radius, weight);
  }
  return robot;
}

Vehicle* OdeWorld::add_diffdrive(const DiffDriveSpec& spec, const Pose2D& pose) {
  // The centre of mass sits between the axle and the caster so the robot rests on both.
  const double com_behind_axle = spec.caster_offset / 4;
  const double z_body = spec.ground_clearance + spec.body_height / 2;
  dBodyID chassis = dBodyCreate(world_);
  Place(chassis, pose, {-com_behind_axle, 0, z_body});
  dMass mass;
  dMassSetBoxTotal(&mass, spec.body_mass, spec.body_length, spec.body_width, spec.body_height);
  SetMoments(mass, spec.body_inertia);
  dBodySetMass(chassis, &mass);
  vehicles_.push_back(std::make_unique<OdeVehicle>(chassis, Vec3{com_behind_axle, 0, 0}));
  OdeVehicle* robot = vehicles_.back().get();

  dGeomSetData(Attach(dCreateBox(moving_, spec.body_length, spec.body_width, spec.body_height), chassis, {0, 0, 0}),
               make_info({Part::kChassis, robot, nullptr, kChassisFriction, 0}));
  dGeomSetData(Attach(dCreateSphere(moving_, spec.caster_radius), chassis,
                      {com_behind_axle - spec.caster_offset, 0, spec.caster_radius - z_body}),
               make_info({Part::kCaster, robot, nullptr, 0, 0}));

  // Wheel 0 is the left one (+y), wheel 1 the right one. Both spin about +y, so a positive
  // speed rolls forward.
  for (double side : {1.0, -1.0}) {
    const Vec3 local{0, side * spec.axle_length / 2, spec.wheel_radius};
    dBodyID wheel = dBodyCreate(world_);
    Place(wheel, pose, local);
    dMassSetSphereTotal(&mass, spec.wheel_mass, spec.wheel_radius);
    dBodySetMass(wheel, &mass);
    dJointID hinge = dJointCreateHinge(world_, nullptr);
    dJointAttach(hinge, wheel, chassis);
    const Vec2 anchor = ToWorld(pose, {local.x, local.y});
    dJointSetHingeAnchor(hinge, anchor.x, anchor.y, local.z);
    dJointSetHingeAxis(hinge, -std::sin(pose.theta), std::cos(pose.theta), 0);
    dGeomID g = dCreateSphere(moving_, spec.wheel_radius);
    dGeomSetBody(g, wheel);
    dGeomSetData(g, make_info({Part::kDriveWheel, robot, nullptr, spec.wheel_friction, 0}));
    // The caster carries the rest: the centre of mass is a quarter of its offset behind the axle.
    const double on_axle = 1 - com_behind_axle / spec.caster_offset;
    const double weight = (spec.body_mass + 2 * spec.wheel_mass) * settings_.gravity * on_axle / 2;
    robot->add_wheel(wheel, hinge, spec.max_wheel_torque, spec.wheel_radius, weight);
  }
  return robot;
}

}  // namespace sanet::physics::ode
