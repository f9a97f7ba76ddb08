// Robots that a client of the server adds to the running world with INIT, as USARSim's clients
// do: the scenario's spawn section says which classes become which robots, how many may be
// added and where they may stand. This unit decides whether a request can be granted; the
// assembly builds the robot.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sim/run_spec.h"

namespace sanet::sim {

class Assembly;

struct SpawnRequest {
  std::string usarsim_class;  // e.g. USARBot.P2DX
  std::string name;           // empty: one is made from the class
  Pose2D pose;                // in sanet's frame (z up)
};

// The robot a request adds, or why it is refused (one sentence for the client).
struct SpawnPlan {
  std::optional<NodeSpec> node;
  std::string usarsim_class;  // as the scenario spells it
  std::string refusal;
};

SpawnPlan PlanSpawn(const Assembly& world, const SpawnRequest& request);

// Whether two class names are the same class (Unreal's names ignore case).
bool SameClass(const std::string& a, const std::string& b);

// What a spawn section offers when it names no classes: USARSim's Pioneers as diffdrive robots
// with their laser, and sanet's own models under their names.
std::vector<SpawnClass> DefaultSpawnClasses();

// Where spawned robots may stand unless the scenario says: the field of `world_size` centred on
// the middle of the scenario's nodes and obstacles (min corner, max corner).
std::pair<Vec2, Vec2> DefaultSpawnRegion(const RunSpec& spec);

}  // namespace sanet::sim
