#include "scenario/urdf_body.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "robots/urdf_drive.h"
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
  if (!in) urdf.Fail("cannot read the URDF file " + path_named + ": " + std::strerror(errno));
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
    if (!wheels.IsMap()) wheels.Fail("a diffdrive's wheels are {left: JOINT, right: JOINT}, its wheel joints");
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

// The wheels' geometry must drive the model: refused at the wheel joint's line, or at the
// scenario's `wheels` line for a joint named twice.
void CheckDrive(const Field& body, const robots::UrdfRobot& robot, robots::ModelKind kind,
                const robots::DriveCentre& centre, const std::string& path) {
  const robots::DriveFault fault = robots::FaultOf(robot, kind, centre);
  if (fault.message.empty()) return;
  const robots::UrdfWheel& wheel = robot.wheels.at(fault.wheel);
  if (fault.scenarios) body.Require("wheels").Fail(fault.message);
  throw ScenarioError(path, wheel.line, "<joint name=\"" + wheel.joint + "\">", fault.message);
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
    // No line: a name the scenario gave that the file lacks, on the scenario's line for it.
    const auto named = body.Get(e.element().rfind("joint", 0) == 0 ? "wheels" : "base_link");
    if (e.line() == 0) (named ? *named : *urdf).Fail(e.what());
    throw ScenarioError(e.file(), e.line(), e.element(), e.message());
  }
  const robots::DriveCentre centre = robots::DriveCentreOf(robot);
  CheckDrive(body, robot, m.kind, centre, path);
  if (m.kind == robots::ModelKind::kDiffDrive)
    robots::ApplyDiffDrive(robot, centre, m.diffdrive);
  else
    robots::ApplyOmni3(robot, centre, m.omni3);
  robots::TreeOf(robot, m.kind, centre, source);
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
