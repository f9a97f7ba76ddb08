#include "robots/urdf_drive.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "robots/kinematics.h"

namespace sanet::robots {
namespace {

double MeanRadius(const std::vector<UrdfWheel>& wheels) {
  double sum = 0;
  for (const UrdfWheel& w : wheels) sum += w.radius;
  return sum / static_cast<double>(wheels.size());
}

double MeanMass(const std::vector<UrdfWheel>& wheels) {
  double sum = 0;
  for (const UrdfWheel& w : wheels) sum += w.mass;
  return sum / static_cast<double>(wheels.size());
}

// A wheel's place from the drive centre, horizontally.
double WheelAngle(const UrdfWheel& w, const DriveCentre& c) {
  return std::atan2(w.pose.xyz[1] - c.y, w.pose.xyz[0] - c.x);
}

// The axis a wheel turns about as the physics drives it forward (its angle growing): across a
// differential drive (+y, left); outwards on an omni3, whose positive spin moves the rim against
// the tangent (robots/kinematics.cc).
std::array<double, 3> ForwardAxis(ModelKind kind, const UrdfWheel& w, const DriveCentre& c) {
  if (kind == ModelKind::kDiffDrive) return {0, 1, 0};
  const double a = WheelAngle(w, c);
  return {std::cos(a), std::sin(a), 0};
}

double Along(const std::array<double, 3>& axis, const std::array<double, 3>& unit) {
  const double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  return norm == 0 ? 0 : (axis[0] * unit[0] + axis[1] * unit[1] + axis[2] * unit[2]) / norm;
}

// The chassis shape's size: x, y, z extents.
std::array<double, 3> Extent(const UrdfShape& s) {
  switch (s.kind) {
    case UrdfShape::Kind::kBox:
      return s.box;
    case UrdfShape::Kind::kCylinder:
      return {2 * s.radius, 2 * s.radius, s.length};
    case UrdfShape::Kind::kSphere:
      break;
  }
  return {2 * s.radius, 2 * s.radius, 2 * s.radius};
}

DriveFault DiffDriveFault(const UrdfRobot& r) {
  const auto &left = r.wheels[0].pose.xyz, &right = r.wheels[1].pose.xyz;
  const double dx = left[0] - right[0], dy = left[1] - right[1];
  if (dy <= 0)
    return {
        "the left wheel is not on the left of the right one (+y is left in the base link's frame): swap "
        "`left` and `right`",
        0};
  if (std::fabs(dx) > 0.02 * dy)
    return {"the axle is not across the base link's x axis (the wheels are " + std::to_string(dx) +
                " m apart along x): sanet drives a differential robot forward along its base link's x",
            0};
  return {};
}

}  // namespace

DriveCentre DriveCentreOf(const UrdfRobot& r) {
  DriveCentre c;
  for (const UrdfWheel& w : r.wheels) {
    c.x += w.pose.xyz[0] / static_cast<double>(r.wheels.size());
    c.y += w.pose.xyz[1] / static_cast<double>(r.wheels.size());
    c.ground_z += w.pose.xyz[2] / static_cast<double>(r.wheels.size());
  }
  c.ground_z -= MeanRadius(r.wheels);
  return c;
}

DriveFault FaultOf(const UrdfRobot& r, ModelKind kind, const DriveCentre& centre) {
  for (std::size_t i = 0; i < r.wheels.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (r.wheels[i].joint == r.wheels[j].joint) return {"names the joint '" + r.wheels[i].joint + "' twice", i, true};
  for (std::size_t i = 0; i < r.wheels.size(); ++i)
    if (std::fabs(Along(r.wheels[i].axis, ForwardAxis(kind, r.wheels[i], centre))) < 0.7)
      return {"the joint's axis does not roll the wheel " +
                  std::string(kind == ModelKind::kDiffDrive ? "forward (it should point across the body, along y)"
                                                            : "round the body (it should point out from the centre)"),
              i};
  if (kind == ModelKind::kDiffDrive) return DiffDriveFault(r);
  try {
    Omni3Kinematics({WheelAngle(r.wheels[0], centre), WheelAngle(r.wheels[1], centre), WheelAngle(r.wheels[2], centre)},
                    1, 1);
  } catch (const std::invalid_argument&) {
    return {"the three wheels' places round the centre cannot drive the body in every direction", 0};
  }
  return {};
}

void ApplyDiffDrive(const UrdfRobot& r, const DriveCentre& centre, physics::DiffDriveSpec& d) {
  d.wheel_radius = MeanRadius(r.wheels);
  d.axle_length = WheelSpacing(r.wheels[0], r.wheels[1]);
  d.wheel_mass = MeanMass(r.wheels);
  d.body_mass = r.chassis_mass;
  d.body_inertia = r.chassis_inertia;
  const UrdfShape& s = r.chassis.front();
  const std::array<double, 3> size = Extent(s);
  d.body_length = size[0], d.body_width = size[1], d.body_height = size[2];
  d.ground_clearance = std::max(0.0, s.pose.xyz[2] - size[2] / 2 - centre.ground_z);
}

void ApplyOmni3(const UrdfRobot& r, const DriveCentre& centre, physics::Omni3Spec& o) {
  o.wheel_radius = MeanRadius(r.wheels);
  o.wheel_mass = MeanMass(r.wheels);
  o.body_mass = r.chassis_mass;
  o.body_inertia = r.chassis_inertia;
  o.wheel_distance = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& xyz = r.wheels[i].pose.xyz;
    o.wheel_distance += std::hypot(xyz[0] - centre.x, xyz[1] - centre.y) / 3;
    o.wheel_angles[i] = WheelAngle(r.wheels[i], centre);
  }
  const UrdfShape& s = r.chassis.front();
  const std::array<double, 3> size = Extent(s);
  o.body_radius = std::max(size[0], size[1]) / 2;
  o.body_height = size[2];
  o.ground_clearance = std::max(0.0, s.pose.xyz[2] - size[2] / 2 - centre.ground_z);
}

void TreeOf(const UrdfRobot& robot, ModelKind kind, const DriveCentre& c, UrdfSource& source) {
  for (const auto& [name, pose] : robot.links)
    source.links[name] = {pose.xyz[0] - c.x, pose.xyz[1] - c.y, pose.xyz[2] - c.ground_z};
  source.root = robot.root;
  source.root_pose = robot.links.at(robot.root);
  source.root_pose.xyz = {source.root_pose.xyz[0] - c.x, source.root_pose.xyz[1] - c.y,
                          source.root_pose.xyz[2] - c.ground_z};
  source.joints = robot.joints;
  for (const UrdfWheel& w : robot.wheels)
    source.wheel_signs.push_back(Along(w.axis, ForwardAxis(kind, w, c)) < 0 ? -1 : 1);
}

}  // namespace sanet::robots
