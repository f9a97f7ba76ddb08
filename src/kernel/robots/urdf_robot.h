// A robot described by a URDF file (ROS's Unified Robot Description Format), read through
// urdfdom, the ROS parser Debian packages: what sanet's wheeled models take from it.
//
// - The wheels are the named continuous joints; each wheel's radius is its link's collision
//   cylinder's, its place the joint's origin through the kinematic chain from the base link.
// - Masses: the wheels' links' and the rest's (the chassis: every other link), from <inertial>.
// - The chassis: the base link's collision shapes (boxes, cylinders, spheres) and their poses.
// - Every link's pose in the base link's frame with the joints at zero (sensor mounts).
//
// urdfdom ignores what it does not know (xacro's elements among them) and logs its errors
// without lines: a TinyXML pass over the same text finds the elements' lines, console_bridge's
// messages are captured rather than printed, and every refusal names the file, the element and
// its line.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sanet::robots {

class UrdfError : public std::runtime_error {
 public:
  UrdfError(const std::string& file, int line, const std::string& element, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }  // 0: the file as a whole
  const std::string& element() const { return element_; }
  const std::string& message() const { return message_; }  // without the file, line and element

 private:
  std::string file_;
  int line_;
  std::string element_;
  std::string message_;
};

struct UrdfPose {
  std::array<double, 3> xyz{};             // m, in the base link's frame
  std::array<double, 4> xyzw{0, 0, 0, 1};  // rotation, a unit quaternion
};

struct UrdfShape {
  enum class Kind { kBox, kCylinder, kSphere } kind = Kind::kBox;
  std::array<double, 3> box{};    // m: x, y, z sizes
  double radius = 0, length = 0;  // m: cylinder (along its z) and sphere
  UrdfPose pose;                  // in the base link's frame
};

struct UrdfWheel {
  std::string joint, link;
  double radius = 0;             // m
  double mass = 0;               // kg
  UrdfPose pose;                 // of the wheel's link in the base link's frame
  std::array<double, 3> axis{};  // the joint's axis in the base link's frame
  int line = 0;                  // of the joint's element
};

// A joint as the robot's tf tree draws it: the child link's frame in the parent's.
struct UrdfJoint {
  std::string name, parent, child;
  UrdfPose origin;                      // the joint at zero
  std::array<double, 3> axis{1, 0, 0};  // in the child's frame
  bool moves = false;                   // continuous, revolute or prismatic
};

struct UrdfRobot {
  std::string file;  // as named
  std::string text;  // the file's content, whole
  std::string name;  // <robot name>
  std::string base_link;
  std::vector<UrdfWheel> wheels;  // in the order asked for
  double chassis_mass = 0;        // kg: every link but the wheels'
  // kg m²: those links' <inertia> together, about their common centre of mass, along the base
  // link's axes (the tensor's diagonal); zeros where the file gives none.
  std::array<double, 3> chassis_inertia{};
  std::vector<UrdfShape> chassis;         // the base link's collision shapes
  std::map<std::string, UrdfPose> links;  // every link's pose, the joints at zero
  std::string root;                       // the root link (the base link unless base_link names another)
  std::vector<UrdfJoint> joints;          // every joint, each after its parent link's own joint
};

// Reads `text` (the content of `file`, named in errors) with the wheels' joint names in order and
// the base link (empty: the URDF's root link). Throws UrdfError.
UrdfRobot ReadUrdf(const std::string& file, const std::string& text, const std::vector<std::string>& wheel_joints,
                   const std::string& base_link = "");

// The distance between two wheels' contact points across the body (their places projected on
// the base link's horizontal plane).
double WheelSpacing(const UrdfWheel& a, const UrdfWheel& b);

}  // namespace sanet::robots
