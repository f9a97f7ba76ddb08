#include "scenario/urdf_body.h"

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

std::vector<std::string> WheelJoints(const Field& body, robots::ModelKind kind) {
  if (kind != robots::ModelKind::kDiffDrive)
    body.Require("urdf").Fail("a URDF describes a diffdrive's body so far (omni3 is to come)");
  const Field wheels = body.Require("wheels");
  wheels.ExpectKeys({"left", "right"});
  return {wheels.Require("left").Text(), wheels.Require("right").Text()};
}

void ApplyDiffDrive(const robots::UrdfRobot& r, physics::DiffDriveSpec& d) {
  const robots::UrdfWheel &left = r.wheels[0], &right = r.wheels[1];
  d.wheel_radius = (left.radius + right.radius) / 2;
  d.axle_length = robots::WheelSpacing(left, right);
  d.wheel_mass = (left.mass + right.mass) / 2;
  d.body_mass = r.chassis_mass;
  for (const robots::UrdfShape& s : r.chassis) {
    if (s.kind != robots::UrdfShape::Kind::kBox) continue;
    d.body_length = s.box[0], d.body_width = s.box[1], d.body_height = s.box[2];
    // The wheels' lowest points are the ground: the box's bottom stands this far above it.
    const double axle_z = (left.pose.xyz[2] + right.pose.xyz[2]) / 2;
    d.ground_clearance = std::max(0.0, s.pose.xyz[2] - s.box[2] / 2 - (axle_z - d.wheel_radius));
    break;
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
  ApplyDiffDrive(robot, m.diffdrive);
  // The ground is under the wheels' lowest points.
  const double ground_z = (robot.wheels[0].pose.xyz[2] + robot.wheels[1].pose.xyz[2]) / 2 - m.diffdrive.wheel_radius;
  for (const auto& [name, pose] : robot.links) source.links[name] = {pose.xyz[0], pose.xyz[1], pose.xyz[2] - ground_z};
  m.urdf = std::make_shared<const robots::UrdfSource>(std::move(source));
}

void PrintUrdfBody(const robots::ModelSpec& m, YAML::Node& body) {
  if (!m.urdf) return;
  YAML::Node urdf(YAML::NodeType::Map);
  urdf["file"] = m.urdf->file;
  urdf["text"] = m.urdf->text;
  body["urdf"] = urdf;
  YAML::Node wheels(YAML::NodeType::Map);
  wheels["left"] = m.urdf->wheels.at(0);
  wheels["right"] = m.urdf->wheels.at(1);
  body["wheels"] = wheels;
  if (!m.urdf->base_link.empty()) body["base_link"] = m.urdf->base_link;
}

}  // namespace sanet::scenario
