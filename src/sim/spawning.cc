#include "sim/spawning.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "sim/assembly.h"

namespace sanet::sim {
namespace {

// Node names end up in CSV rows and file names (packets/<name>.csv), as in scenarios.
bool SafeName(const std::string& name) {
  if (name.empty() || name.size() > 64 || name == "." || name == "..") return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

std::string Metres(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", std::fabs(v) < 0.005 ? 0.0 : v);  // never "-0.00"
  return text;
}

std::string Point(Vec2 p) { return "(" + Metres(p.x) + ", " + Metres(p.y) + ")"; }

// A name from the class (USARBot.P2DX -> P2DX-1, P2DX-2, ...) that no node has yet.
std::string NewName(const Assembly& world, const std::string& usarsim_class) {
  std::string stem = usarsim_class.substr(usarsim_class.rfind('.') + 1);
  if (!SafeName(stem + "-1")) stem = "robot";
  for (int k = 1;; ++k)
    if (!world.Lookup(stem + "-" + std::to_string(k))) return stem + "-" + std::to_string(k);
}

// The distance from `p` to the box, seen from above (0 inside it).
double DistanceToBox(Vec2 p, const physics::StaticBox& box) {
  const double dx = p.x - box.center.x, dy = p.y - box.center.y;
  const double c = std::cos(box.yaw), s = std::sin(box.yaw);
  const double along = c * dx + s * dy, across = -s * dx + c * dy;
  const double out_along = std::max(0.0, std::fabs(along) - box.size.x / 2);
  const double out_across = std::max(0.0, std::fabs(across) - box.size.y / 2);
  return std::hypot(out_along, out_across);
}

const SpawnClass* FindClass(const SpawnSpec& spawn, const std::string& name) {
  for (const SpawnClass& c : spawn.classes)
    if (SameClass(c.usarsim_class, name)) return &c;
  return nullptr;
}

std::string ClassList(const SpawnSpec& spawn) {
  std::string list;
  for (const SpawnClass& c : spawn.classes) list += (list.empty() ? "" : ", ") + c.usarsim_class;
  return list;
}

// Why the body cannot stand at `pose`: outside the region, in an obstacle, on another body.
std::string PlaceRefusal(const Assembly& world, const robots::ModelSpec& model, const Pose2D& pose) {
  const RunSpec& spec = world.spec();
  const auto& [low, high] = spec.spawn->region;
  const Vec2 p = pose.position();
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(pose.theta)) return "the pose is not finite";
  if (p.x < low.x || p.x > high.x || p.y < low.y || p.y > high.y)
    return Point(p) + " is outside spawn.region, which spans x " + Metres(low.x) + " to " + Metres(high.x) +
           " m and y " + Metres(low.y) + " to " + Metres(high.y) + " m (sanet's frame: y to the left)";
  const double radius = robots::FootprintRadius(model);
  for (std::size_t i = 0; i < spec.obstacles.size(); ++i)
    if (DistanceToBox(p, spec.obstacles[i].box) < radius)
      return Point(p) + " is inside world.obstacles[" + std::to_string(i) + "], a " + spec.obstacles[i].kind +
             " (a body of radius " + Metres(radius) + " m does not fit there)";
  for (NodeId id = 0; id < world.NodeCount(); ++id) {
    const double gap = Norm(world.TruePose(id).position() - p);
    if (gap < radius + robots::FootprintRadius(spec.nodes[id].model))
      return Point(p) + " is taken by " + world.NameOf(id) + ", " + Metres(gap) + " m away (the two bodies need " +
             Metres(radius + robots::FootprintRadius(spec.nodes[id].model)) + " m)";
  }
  return "";
}

}  // namespace

bool SameClass(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

SpawnPlan PlanSpawn(const Assembly& world, const SpawnRequest& request) {
  const RunSpec& spec = world.spec();
  if (!spec.spawn) return {std::nullopt, "", "this scenario has no spawn section: no robots may be added"};
  const SpawnSpec& spawn = *spec.spawn;
  const SpawnClass* cls = FindClass(spawn, request.usarsim_class);
  if (!cls)
    return {std::nullopt, "",
            "class '" + request.usarsim_class + "' may not be spawned here (allowed: " + ClassList(spawn) + ")"};
  const std::string name = request.name.empty() ? NewName(world, request.usarsim_class) : request.name;
  if (!SafeName(name))
    return {std::nullopt, "", "'" + name + "' is not a robot name: up to 64 letters, digits, '_', '-' and '.'"};
  if (world.Lookup(name)) return {std::nullopt, "", "the name '" + name + "' is taken by another node"};
  if (world.spawned() >= spawn.max)
    return {std::nullopt, "",
            std::to_string(world.spawned()) + " robots have been added already, as many as this " +
                "scenario allows (spawn.max)"};
  if (std::string why = PlaceRefusal(world, cls->model, request.pose); !why.empty()) return {std::nullopt, "", why};
  NodeSpec node;
  node.name = name;
  node.model = cls->model;
  node.pose = request.pose;
  node.radio = cls->radio;
  return {node, cls->usarsim_class, ""};
}

std::vector<SpawnClass> DefaultSpawnClasses() {
  using robots::ModelKind;
  using robots::ModelSpec;
  std::vector<SpawnClass> classes;
  for (const char* pioneer : {"USARBot.P2DX", "USARBot.P2AT", "USARBot.P3AT"})
    classes.push_back({pioneer, ModelSpec::Defaults(ModelKind::kDiffDrive), {}});
  classes.push_back({"sanet.DiffDrive", ModelSpec::Defaults(ModelKind::kDiffDrive), {}});
  classes.push_back({"sanet.Omni3", ModelSpec::Defaults(ModelKind::kOmni3), {}});
  return classes;
}

std::pair<Vec2, Vec2> DefaultSpawnRegion(const RunSpec& spec) {
  Vec2 low{HUGE_VAL, HUGE_VAL}, high{-HUGE_VAL, -HUGE_VAL};
  const auto hold = [&](Vec2 p) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y)};
  };
  for (const NodeSpec& n : spec.nodes) hold(n.pose.position());
  for (const Obstacle& o : spec.obstacles) hold({o.box.center.x, o.box.center.y});
  if (low.x > high.x) low = high = {0, 0};
  const Vec2 middle = (low + high) * 0.5, half = spec.world_size * 0.5;
  return {middle - half, middle + half};
}

}  // namespace sanet::sim
