#include "robot_server/spawn_policy.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "core/metres.h"

namespace sanet::robot_server {
namespace {

using sections::SpawnClass;
using sections::SpawnSpec;

// Node names end up in CSV rows and file names (packets/<name>.csv), as in scenarios.
bool SafeName(const std::string& name) {
  if (name.empty() || name.size() > 64 || name == "." || name == "..") return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

std::string Point(Vec2 p) { return "(" + Metres(p.x) + ", " + Metres(p.y) + ")"; }

// A name from the class (USARBot.P2DX -> P2DX-1, P2DX-2, ...) that no node has yet.
std::string NewName(const sim::Driver& world, const std::string& usarsim_class) {
  std::string stem = usarsim_class.substr(usarsim_class.rfind('.') + 1);
  if (!SafeName(stem + "-1")) stem = "robot";
  for (int k = 1;; ++k)
    if (!world.Lookup(stem + "-" + std::to_string(k))) return stem + "-" + std::to_string(k);
}

const SpawnClass* FindClass(const SpawnSpec& spawn, const std::string& name) {
  for (const SpawnClass& c : spawn.classes)
    if (sections::SameClass(c.usarsim_class, name)) return &c;
  return nullptr;
}

std::string ClassList(const SpawnSpec& spawn) {
  std::string list;
  for (const SpawnClass& c : spawn.classes) list += (list.empty() ? "" : ", ") + c.usarsim_class;
  return list;
}

// Why the body cannot stand at `pose`: outside the region, in an obstacle, on another body.
std::string PlaceRefusal(const sim::Driver& world, const SpawnSpec& spawn, const robots::ModelSpec& model,
                         const Pose2D& pose) {
  const auto& [low, high] = spawn.region;
  const Vec2 p = pose.position();
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(pose.theta)) return "the pose is not finite";
  if (p.x < low.x || p.x > high.x || p.y < low.y || p.y > high.y)
    return Point(p) + " is outside spawn.region, which spans x " + Metres(low.x) + " to " + Metres(high.x) +
           " m and y " + Metres(low.y) + " to " + Metres(high.y) + " m (sanet's frame: y to the left)";
  const double radius = robots::FootprintRadius(model);
  const std::vector<sim::Obstacle>& obstacles = world.spec().obstacles;
  for (std::size_t i = 0; i < obstacles.size(); ++i)
    if (physics::DistanceFromAbove(p, obstacles[i].box) < radius)
      return Point(p) + " is inside " +
             (obstacles[i].from_map ? std::string("a wall of world.map")
                                    : "world.obstacles[" + std::to_string(i) + "], a " + obstacles[i].kind) +
             " (a body of radius " + Metres(radius) + " m does not fit there)";
  for (NodeId id = 0; id < world.NodeCount(); ++id) {
    const double gap = Norm(world.PoseOf(id).position() - p);
    const double needed = radius + robots::FootprintRadius(world.Spec(id).model);
    if (gap < needed)
      return Point(p) + " is taken by " + world.NameOf(id) + ", " + Metres(gap) + " m away (the two bodies need " +
             Metres(needed) + " m)";
  }
  return "";
}

}  // namespace

SpawnPlan PlanSpawn(const sim::Driver& world, const std::optional<SpawnSpec>& spawn, const SpawnRequest& request) {
  if (!spawn) return {std::nullopt, "", "this scenario has no spawn section: no robots may be added"};
  const SpawnClass* cls = FindClass(*spawn, request.usarsim_class);
  if (!cls)
    return {std::nullopt, "",
            "class '" + request.usarsim_class + "' may not be spawned here (allowed: " + ClassList(*spawn) + ")"};
  const std::string name = request.name.empty() ? NewName(world, request.usarsim_class) : request.name;
  if (!SafeName(name))
    return {std::nullopt, "", "'" + name + "' is not a robot name: up to 64 letters, digits, '_', '-' and '.'"};
  if (world.Lookup(name)) return {std::nullopt, "", "the name '" + name + "' is taken by another node"};
  if (world.SpawnedCount() >= spawn->max)
    return {std::nullopt, "",
            std::to_string(world.SpawnedCount()) + " robots have been added already, as many as this " +
                "scenario allows (spawn.max)"};
  if (std::string why = PlaceRefusal(world, *spawn, cls->model, request.pose); !why.empty())
    return {std::nullopt, "", why};
  sim::NodeSpec node;
  node.name = name;
  node.model = cls->model;
  node.pose = request.pose;
  node.radio = cls->radio;
  node.energy = cls->energy;
  return {node, cls->usarsim_class, ""};
}

}  // namespace sanet::robot_server
