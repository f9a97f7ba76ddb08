// What a URDF robot's wheels and chassis make of sanet's wheeled models (robots/urdf_robot.h reads
// the file): the body's numbers, the frame the physics drives it in, and what the file must hold
// for that to be the robot it describes.
//
// sanet turns a robot about its drive centre (a differential drive's axle middle, an omni3's
// wheels' centre), on the ground under it: that point, not the URDF's base link origin, is the
// robot's R/base_link, and a sensor's mount and the URDF's links are placed from there.
#pragma once

#include <string>

#include "physics/physics_world.h"
#include "robots/node_model.h"
#include "robots/urdf_robot.h"

namespace sanet::robots {

// The drive centre in the base link's frame: x, y where it turns, z of the ground (the wheels'
// lowest points).
struct DriveCentre {
  double x = 0, y = 0, ground_z = 0;
};
DriveCentre DriveCentreOf(const UrdfRobot& robot);

// Why these wheels cannot drive the model `kind` as sanet simulates it (empty: they can), and
// the wheel at fault (its index in robot.wheels): a joint named twice, a differential drive's
// axle not across the base link's x axis or its left wheel on the right, a wheel turning about
// an axis that does not roll it, an omni3 whose wheels' directions give no inverse.
struct DriveFault {
  std::string message;
  std::size_t wheel = 0;
  bool scenarios = false;  // the scenario's mistake (a joint named twice), not the file's
};
DriveFault FaultOf(const UrdfRobot& robot, ModelKind kind, const DriveCentre& centre);

void ApplyDiffDrive(const UrdfRobot& robot, const DriveCentre& centre, physics::DiffDriveSpec& spec);
void ApplyOmni3(const UrdfRobot& robot, const DriveCentre& centre, physics::Omni3Spec& spec);

// The tf tree's part of `source` (robots/node_model.h): every link's place and the root's pose
// from the drive centre on the ground, the joints, each wheel's sign.
void TreeOf(const UrdfRobot& robot, ModelKind kind, const DriveCentre& centre, UrdfSource& source);

}  // namespace sanet::robots
