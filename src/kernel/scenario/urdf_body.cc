#include "scenario/urdf_body.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "robots/urdf_robot.h"

namespace sanet::scenario {
namespace {

// The URDF's text: from the file named (relative to the scenario), or as the effective scenario
// carries it (`{file, text}`). `path_named`: the file as errors name it.
robots::UrdfSource Source(const Field& urdf, std::string& path_named) {
  robots::UrdfSource s;
  if (urdf.IsMap()) {
    urdf.ExpectKeys({"file", "text"});
    s.file = path_named = urdf.Require("file").Text();
    s.text = urdf.Require("text").Text();
    return s;
  }
  s.file = urdf.Text();
  std::filesystem::path path(s.file);
  if (path.is_relative()) path = std::filesystem::path(urdf.file()).parent_path() / path;
  path_named = path.lexically_normal().string();
  std::ifstream in(path);
  if (!in) urdf.Fail("cannot read the URDF file " + path.string());
  std::stringstream text;
  text << in.rdbuf();
  s.text = text.str();
  return s;
}

// A differential drive's wheels by side (`{left, right}`), an omni3's as a list of three.
std::vector<std::string> WheelJoints(const Field& body, robots::ModelKind kind) {
  if (kind != robots::ModelKind::kDiffDrive && kind != robots::ModelKind::kOmni3)
    body.Require("urdf").Fail("a URDF describes a diffdrive's or an omni3's body");
  const Field wheels = body.Require("wheels");
  if (kind == robots::ModelKind::kDiffDrive) {
    wheels.ExpectKeys({"left", "right"});
    return {wheels.Require("left").Text(), wheels.Require("right").Text()};
  }
  const std::vector<Field> items = wheels.IsSequence() ? wheels.Items() : std::vector<Field>{};
  if (items.size() != 3)
    wheels.Fail(
        "an omni3's wheels are a list of its three wheel joints, e.g. [wheel_1_joint, wheel_2_joint, "
        "wheel_3_joint]");
  std::vector<std::string> joints;
  for (const Field& joint : items) joints.push_back(joint.Text());
  return joints;
}

double MeanRadius(const std::vector<robots::UrdfWheel>& wheels) {
  double sum = 0;
  for (const robots::UrdfWheel& w : wheels) sum += w.radius;
  return sum / static_cast<double>(wheels.size());
}

double MeanMass(const std::vector<robots::UrdfWheel>& wheels) {
  double sum = 0;
  for (const robots::UrdfWheel& w : wheels) sum += w.mass;
  return sum / static_cast<double>(wheels.size());
}

// Where the ground is in the base link's frame: under the wheels' lowest points.
double GroundZ(const robots::UrdfRobot& r) {
  double axle_z = 0;
  for (const robots::UrdfWheel& w : r.wheels) axle_z += w.pose.xyz[2];
  return axle_z / static_cast<double>(r.wheels.size()) - MeanRadius(r.wheels);
}

void ApplyDiffDrive(const robots::UrdfRobot& r, physics::DiffDriveSpec& d) {
  d.wheel_radius = MeanRadius(r.wheels);
  d.axle_length = robots::WheelSpacing(r.wheels[0], r.wheels[1]);
  d.wheel_mass = MeanMass(r.wheels);
  d.body_mass = r.chassis_mass;
  for (const robots::UrdfShape& s : r.chassis) {
    if (s.kind != robots::UrdfShape::Kind::kBox) continue;
    d.body_length = s.box[0], d.body_width = s.box[1], d.body_height = s.box[2];
    d.ground_clearance = std::max(0.0, s.pose.xyz[2] - s.box[2] / 2 - GroundZ(r));
    break;
  }
}

// An omni3's body is a cylinder: the chassis's first cylinder, sphere or box (its larger half
// side as the radius), standing where the URDF puts its bottom. Each wheel's angle and distance
// are its place seen from the base link's origin.
void ApplyOmni3(const robots::UrdfRobot& r, physics::Omni3Spec& o) {
  o.wheel_radius = MeanRadius(r.wheels);
  o.wheel_mass = MeanMass(r.wheels);
  o.body_mass = r.chassis_mass;
  o.wheel_distance = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& xyz = r.wheels[i].pose.xyz;
    o.wheel_distance += std::hypot(xyz[0], xyz[1]) / 3;
    o.wheel_angles[i] = std::atan2(xyz[1], xyz[0]);
  }
  const robots::UrdfShape& s = r.chassis.front();
  const double height = s.kind == robots::UrdfShape::Kind::kBox        ? s.box[2]
                        : s.kind == robots::UrdfShape::Kind::kCylinder ? s.length
                                                                       : 2 * s.radius;
  o.body_radius = s.kind == robots::UrdfShape::Kind::kBox ? std::max(s.box[0], s.box[1]) / 2 : s.radius;
  o.body_height = height;
  o.ground_clearance = std::max(0.0, s.pose.xyz[2] - height / 2 - GroundZ(r));
}

// The axis a wheel turns about as the physics drives it forward (its angle growing): across a
// differential drive (+y, left), inwards on an omni3 (whose wheels push the body
// counter-clockwise round its centre: robots/kinematics.h).
std::array<double, 3> ForwardAxis(robots::ModelKind kind, const robots::UrdfWheel& w) {
  if (kind == robots::ModelKind::kDiffDrive) return {0, 1, 0};
  const double a = std::atan2(w.pose.xyz[1], w.pose.xyz[0]);
  return {-std::cos(a), -std::sin(a), 0};
}

// What the tf tree needs: the joints, the root's pose above the ground, each wheel's sign.
void TreeOf(const robots::UrdfRobot& robot, robots::ModelKind kind, double ground_z, robots::UrdfSource& source) {
  for (const auto& [name, pose] : robot.links) source.links[name] = {pose.xyz[0], pose.xyz[1], pose.xyz[2] - ground_z};
  source.root = robot.root;
  source.root_pose = robot.links.at(robot.root);
  source.root_pose.xyz[2] -= ground_z;
  source.joints = robot.joints;
  for (const robots::UrdfWheel& w : robot.wheels) {
    const std::array<double, 3> forward = ForwardAxis(kind, w);
    const double along = w.axis[0] * forward[0] + w.axis[1] * forward[1] + w.axis[2] * forward[2];
    source.wheel_signs.push_back(along < 0 ? -1 : 1);
  }
}

}  // namespace

void ReadUrdfBody(const Field& body, robots::ModelSpec& m) {
  const auto urdf = body.Get("urdf");
  if (!urdf) {
    for (const char* key : {"wheels", "base_link"})
      if (auto given = body.Get(key)) given->Fail("goes with `urdf`: the joints and link of a URDF file");
    return;
  }
  std::string path;
  robots::UrdfSource source = Source(*urdf, path);
  source.wheels = WheelJoints(body, m.kind);
  if (auto base = body.Get("base_link")) source.base_link = base->Text();
  robots::UrdfRobot robot;
  try {
    robot = robots::ReadUrdf(path, source.text, source.wheels, source.base_link);
  } catch (const robots::UrdfError& e) {
    if (e.line() == 0) body.Get(e.element().rfind("joint", 0) == 0 ? "wheels" : "base_link")->Fail(e.what());
    throw ScenarioError(e.file(), e.line(), e.element(), e.message());
  }
  if (m.kind == robots::ModelKind::kDiffDrive)
    ApplyDiffDrive(robot, m.diffdrive);
  else
    ApplyOmni3(robot, m.omni3);
  TreeOf(robot, m.kind, GroundZ(robot), source);
  m.urdf = std::make_shared<const robots::UrdfSource>(std::move(source));
}

void PrintUrdfBody(const robots::ModelSpec& m, YAML::Node& body) {
  if (!m.urdf) return;
  YAML::Node urdf(YAML::NodeType::Map);
  urdf["file"] = m.urdf->file;
  urdf["text"] = m.urdf->text;
  body["urdf"] = urdf;
  if (m.kind == robots::ModelKind::kDiffDrive) {
    YAML::Node wheels(YAML::NodeType::Map);
    wheels["left"] = m.urdf->wheels.at(0);
    wheels["right"] = m.urdf->wheels.at(1);
    body["wheels"] = wheels;
  } else {
    YAML::Node wheels(YAML::NodeType::Sequence);
    for (const std::string& joint : m.urdf->wheels) wheels.push_back(joint);
    wheels.SetStyle(YAML::EmitterStyle::Flow);
    body["wheels"] = wheels;
  }
  if (!m.urdf->base_link.empty()) body["base_link"] = m.urdf->base_link;
}

}  // namespace sanet::scenario
