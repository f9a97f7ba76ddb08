#include "robots/urdf_robot.h"

#include <console_bridge/console.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>

namespace sanet::robots {
namespace {

std::string Where(const std::string& file, int line, const std::string& element) {
  return file + (line > 0 ? ":" + std::to_string(line) : "") + ": " + element;
}

// The lines of the file's <link> and <joint> elements by name, from a TinyXML pass (urdfdom's
// own reading keeps none); xacro and XML faults found on the way are refused here.
struct ElementLines {
  std::map<std::string, int> links, joints;
  int robot = 0;
};

void RefuseXacro(const std::string& file, const TiXmlElement& e) {
  const std::string name = e.ValueStr();
  bool xacro = name.rfind("xacro:", 0) == 0;
  for (const TiXmlAttribute* a = e.FirstAttribute(); a && !xacro; a = a->Next())
    // (a namespace declaration alone is no xacro: older xacro output keeps it)
    xacro = std::string(a->Value()).find("${") != std::string::npos ||
            std::string(a->Value()).find("$(") != std::string::npos;
  if (!xacro) return;
  throw UrdfError(
      file, e.Row(), "<" + name + ">",
      "is xacro, which urdfdom would ignore: expand the file first (`xacro robot.urdf.xacro > robot.urdf`, on "
      "a machine with ROS; xacro is not packaged in Debian 12)");
}

void Walk(const std::string& file, const TiXmlElement& e, ElementLines& lines) {
  RefuseXacro(file, e);
  const char* name = e.Attribute("name");
  if (name && e.ValueStr() == "link") lines.links.emplace(name, e.Row());
  if (name && e.ValueStr() == "joint") lines.joints.emplace(name, e.Row());
  for (const TiXmlElement* child = e.FirstChildElement(); child; child = child->NextSiblingElement())
    Walk(file, *child, lines);
}

ElementLines FindLines(const std::string& file, const std::string& text) {
  TiXmlDocument doc;
  doc.Parse(text.c_str(), nullptr, TIXML_ENCODING_UTF8);
  if (doc.Error())
    throw UrdfError(file, std::max(1, doc.ErrorRow()), "the XML",
                    std::string(doc.ErrorDesc()) + " (column " + std::to_string(doc.ErrorCol()) + ")");
  const TiXmlElement* robot = doc.RootElement();
  if (!robot || robot->ValueStr() != "robot")
    throw UrdfError(file, robot ? robot->Row() : 1, robot ? "<" + robot->ValueStr() + ">" : "the file",
                    "a URDF's root element is <robot>");
  ElementLines lines;
  lines.robot = robot->Row();
  Walk(file, *robot, lines);
  return lines;
}

// console_bridge's messages while urdfdom parses, instead of its printing them. The handler is
// process-wide: one parse at a time.
class CapturedMessages : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) messages.push_back(text);
  }
  std::vector<std::string> messages;
};

urdf::ModelInterfaceSharedPtr Parse(const std::string& file, const std::string& text, const ElementLines& lines) {
  static std::mutex parsing;
  std::lock_guard<std::mutex> one_at_a_time(parsing);
  CapturedMessages captured;
  console_bridge::useOutputHandler(&captured);
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(text);
  console_bridge::restorePreviousOutputHandler();
  if (model) return model;
  std::string why;
  for (const std::string& m : captured.messages) why += (why.empty() ? "" : "; ") + m;
  if (why.empty()) why = "urdfdom cannot read it";
  // Its messages name the element in quotes or brackets: give the line of the first named.
  for (const auto& [kind, named] : {std::pair{"joint", &lines.joints}, {"link", &lines.links}})
    for (const auto& [name, row] : *named)
      if (why.find("'" + name + "'") != std::string::npos || why.find("[" + name + "]") != std::string::npos)
        throw UrdfError(file, row, std::string("<") + kind + " name=\"" + name + "\">", why);
  throw UrdfError(file, lines.robot, "<robot>", why);
}

UrdfPose Compose(const UrdfPose& a, const urdf::Pose& b) {
  const urdf::Rotation qa(a.xyzw[0], a.xyzw[1], a.xyzw[2], a.xyzw[3]);
  const urdf::Vector3 p = qa * b.position;
  const urdf::Rotation q = qa * b.rotation;
  return {{a.xyz[0] + p.x, a.xyz[1] + p.y, a.xyz[2] + p.z}, {q.x, q.y, q.z, q.w}};
}

UrdfPose Inverse(const UrdfPose& a) {
  const urdf::Rotation inverse(-a.xyzw[0], -a.xyzw[1], -a.xyzw[2], a.xyzw[3]);
  const urdf::Vector3 p = inverse * urdf::Vector3(-a.xyz[0], -a.xyz[1], -a.xyz[2]);
  return {{p.x, p.y, p.z}, {inverse.x, inverse.y, inverse.z, inverse.w}};
}

urdf::Pose AsUrdf(const UrdfPose& a) {
  urdf::Pose p;
  p.position = urdf::Vector3(a.xyz[0], a.xyz[1], a.xyz[2]);
  p.rotation = urdf::Rotation(a.xyzw[0], a.xyzw[1], a.xyzw[2], a.xyzw[3]);
  return p;
}

// Every link's pose in the root link's frame, the joints at zero.
std::map<std::string, UrdfPose> PosesFromRoot(const urdf::ModelInterface& model) {
  std::map<std::string, UrdfPose> poses;
  std::deque<urdf::LinkConstSharedPtr> open = {model.getRoot()};
  poses[model.getRoot()->name] = UrdfPose{};
  while (!open.empty()) {
    const urdf::LinkConstSharedPtr link = open.front();
    open.pop_front();
    for (const urdf::JointSharedPtr& joint : link->child_joints) {
      poses[joint->child_link_name] = Compose(poses[link->name], joint->parent_to_joint_origin_transform);
      open.push_back(model.getLink(joint->child_link_name));
    }
  }
  return poses;
}

// Every joint, from the root down (a parent link's joint before its children's).
std::vector<UrdfJoint> JointsFromRoot(const urdf::ModelInterface& model) {
  std::vector<UrdfJoint> joints;
  std::deque<urdf::LinkConstSharedPtr> open = {model.getRoot()};
  while (!open.empty()) {
    const urdf::LinkConstSharedPtr link = open.front();
    open.pop_front();
    for (const urdf::JointSharedPtr& joint : link->child_joints) {
      const urdf::Pose& o = joint->parent_to_joint_origin_transform;
      UrdfJoint j{joint->name, link->name, joint->child_link_name, {}, {}, false};
      j.origin = {{o.position.x, o.position.y, o.position.z}, {o.rotation.x, o.rotation.y, o.rotation.z, o.rotation.w}};
      j.axis = {joint->axis.x, joint->axis.y, joint->axis.z};
      j.moves = joint->type == urdf::Joint::CONTINUOUS || joint->type == urdf::Joint::REVOLUTE ||
                joint->type == urdf::Joint::PRISMATIC;
      joints.push_back(j);
      open.push_back(model.getLink(joint->child_link_name));
    }
  }
  return joints;
}

using Matrix = std::array<std::array<double, 3>, 3>;

Matrix RotationOf(const UrdfPose& p) {
  const double x = p.xyzw[0], y = p.xyzw[1], z = p.xyzw[2], w = p.xyzw[3];
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
           {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
           {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
}

// One link's mass: where its centre is (in the base link's frame) and its tensor along the base
// link's axes (R I R^T).
struct PointMass {
  double mass;
  std::array<double, 3> at;
  Matrix inertia;
};

PointMass MassOf(const urdf::Inertial& inertial, const UrdfPose& link) {
  const UrdfPose centre = Compose(link, inertial.origin);
  const Matrix r = RotationOf(centre);
  const Matrix own = {{{inertial.ixx, inertial.ixy, inertial.ixz},
                       {inertial.ixy, inertial.iyy, inertial.iyz},
                       {inertial.ixz, inertial.iyz, inertial.izz}}};
  Matrix turned{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) turned[i][j] += r[i][k] * own[k][l] * r[j][l];
  return {inertial.mass, centre.xyz, turned};
}

// The masses' moments about their common centre (parallel axes), along the base link's axes.
std::array<double, 3> Moments(const std::vector<PointMass>& masses) {
  double total = 0;
  std::array<double, 3> centre{};
  for (const PointMass& m : masses) {
    total += m.mass;
    for (int i = 0; i < 3; ++i) centre[i] += m.mass * m.at[i];
  }
  if (total <= 0) return {};
  for (double& c : centre) c /= total;
  std::array<double, 3> moments{};
  for (const PointMass& m : masses) {
    const std::array<double, 3> d = {m.at[0] - centre[0], m.at[1] - centre[1], m.at[2] - centre[2]};
    const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    for (int i = 0; i < 3; ++i) moments[i] += m.inertia[i][i] + m.mass * (d2 - d[i] * d[i]);
  }
  return moments;
}

std::string JointNames(const urdf::ModelInterface& model) {
  std::string names;
  for (const auto& [name, joint] : model.joints_) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "none" : names;
}

UrdfWheel ReadWheel(const std::string& file, const urdf::ModelInterface& model, const ElementLines& lines,
                    const std::string& name, const std::map<std::string, UrdfPose>& poses) {
  const urdf::JointConstSharedPtr joint = model.getJoint(name);
  if (!joint)
    throw UrdfError(file, 0, "joint '" + name + "'",
                    "the file has no joint of that name (its joints: " + JointNames(model) + ")");
  const int line = lines.joints.count(name) ? lines.joints.at(name) : 0;
  if (joint->type != urdf::Joint::CONTINUOUS)
    throw UrdfError(file, line, "<joint name=\"" + name + "\">",
                    "a wheel turns on a continuous joint (type=\"continuous\"); this one is not");
  const urdf::LinkConstSharedPtr link = model.getLink(joint->child_link_name);
  UrdfWheel w{name, link->name, 0, link->inertial ? link->inertial->mass : 0, poses.at(link->name), {}, line};
  const UrdfPose& p = w.pose;
  const urdf::Vector3 axis = urdf::Rotation(p.xyzw[0], p.xyzw[1], p.xyzw[2], p.xyzw[3]) * joint->axis;
  w.axis = {axis.x, axis.y, axis.z};
  for (const urdf::CollisionSharedPtr& c : link->collision_array)  // the largest, if there are more
    if (c->geometry && c->geometry->type == urdf::Geometry::CYLINDER)
      w.radius = std::max(w.radius, static_cast<const urdf::Cylinder&>(*c->geometry).radius);
  const int link_line = lines.links.count(link->name) ? lines.links.at(link->name) : line;
  if (w.radius <= 0)
    throw UrdfError(file, link_line, "<link name=\"" + link->name + "\">",
                    "a wheel's link needs a <collision> cylinder: its radius is the wheel's");
  if (w.mass <= 0)
    throw UrdfError(file, link_line, "<link name=\"" + link->name + "\">",
                    "a wheel's link needs an <inertial> mass above 0: the physics moves it");
  return w;
}

std::vector<UrdfShape> ReadChassis(const std::string& file, const urdf::Link& base, const UrdfPose& base_pose,
                                   const ElementLines& lines) {
  std::vector<UrdfShape> shapes;
  bool mesh = false;
  for (const urdf::CollisionSharedPtr& c : base.collision_array) {
    if (!c->geometry) continue;
    UrdfShape s;
    s.pose = Compose(base_pose, c->origin);
    switch (c->geometry->type) {
      case urdf::Geometry::BOX: {
        const urdf::Vector3& d = static_cast<const urdf::Box&>(*c->geometry).dim;
        s.kind = UrdfShape::Kind::kBox, s.box = {d.x, d.y, d.z};
        break;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(*c->geometry);
        s.kind = UrdfShape::Kind::kCylinder, s.radius = cylinder.radius, s.length = cylinder.length;
        break;
      }
      case urdf::Geometry::SPHERE:
        s.kind = UrdfShape::Kind::kSphere, s.radius = static_cast<const urdf::Sphere&>(*c->geometry).radius;
        break;
      default:
        mesh = true;
        continue;
    }
    shapes.push_back(s);
  }
  if (shapes.empty()) {
    const int line = lines.links.count(base.name) ? lines.links.at(base.name) : lines.robot;
    throw UrdfError(file, line, "<link name=\"" + base.name + "\">",
                    mesh ? "its collision is a mesh only: add a <collision> box, cylinder or sphere that bounds it "
                           "(sanet does not compute shapes from meshes)"
                         : "the base link needs a <collision> box, cylinder or sphere: the chassis sanet simulates "
                           "(`base_link` names the link that carries it; the default is the URDF's root)");
  }
  return shapes;
}

}  // namespace

UrdfError::UrdfError(const std::string& file, int line, const std::string& element, const std::string& message)
    : std::runtime_error(Where(file, line, element) + ": " + message),
      file_(file),
      line_(line),
      element_(element),
      message_(message) {}

UrdfRobot ReadUrdf(const std::string& file, const std::string& text, const std::vector<std::string>& wheel_joints,
                   const std::string& base_link) {
  const ElementLines lines = FindLines(file, text);
  const urdf::ModelInterfaceSharedPtr model = Parse(file, text, lines);
  UrdfRobot r;
  r.file = file, r.text = text, r.name = model->getName();
  r.base_link = base_link.empty() ? model->getRoot()->name : base_link;
  const urdf::LinkConstSharedPtr base = model->getLink(r.base_link);
  if (!base) throw UrdfError(file, 0, "link '" + r.base_link + "'", "the file has no link of that name");
  const std::map<std::string, UrdfPose> from_root = PosesFromRoot(*model);
  const UrdfPose root_in_base = Inverse(from_root.at(r.base_link));
  for (const auto& [name, pose] : from_root) r.links[name] = Compose(root_in_base, AsUrdf(pose));
  for (const std::string& joint : wheel_joints) r.wheels.push_back(ReadWheel(file, *model, lines, joint, r.links));
  r.chassis = ReadChassis(file, *base, UrdfPose{}, lines);
  r.root = model->getRoot()->name;
  r.joints = JointsFromRoot(*model);
  std::vector<PointMass> chassis;
  for (const auto& [name, link] : model->links_) {
    const std::string& link_name = name;  // a lambda cannot capture a structured binding in C++17
    const bool wheel =
        std::any_of(r.wheels.begin(), r.wheels.end(), [&](const UrdfWheel& w) { return w.link == link_name; });
    if (wheel || !link->inertial) continue;
    r.chassis_mass += link->inertial->mass;
    chassis.push_back(MassOf(*link->inertial, r.links.at(name)));
  }
  r.chassis_inertia = Moments(chassis);
  const std::array<double, 3>& i = r.chassis_inertia;
  if (std::min({i[0], i[1], i[2]}) <= 0) r.chassis_inertia = {};
  for (int k = 0; k < 3 && i[0] > 0; ++k)
    if (i[k] > i[(k + 1) % 3] + i[(k + 2) % 3] + 1e-12)
      throw UrdfError(file, lines.links.count(r.base_link) ? lines.links.at(r.base_link) : lines.robot,
                      "<link name=\"" + r.base_link + "\">",
                      "the chassis links' <inertia> give moments no body has (one above the sum of the other two): "
                      "check ixx, iyy and izz");
  if (r.chassis_mass <= 0)
    throw UrdfError(file, lines.links.count(r.base_link) ? lines.links.at(r.base_link) : lines.robot,
                    "<link name=\"" + r.base_link + "\">",
                    "the links other than the wheels weigh nothing: give the chassis an <inertial> mass above 0");
  return r;
}

double WheelSpacing(const UrdfWheel& a, const UrdfWheel& b) {
  return std::hypot(a.pose.xyz[0] - b.pose.xyz[0], a.pose.xyz[1] - b.pose.xyz[1]);
}

}  // namespace sanet::robots
