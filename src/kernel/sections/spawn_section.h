// The scenario's `spawn` section: which robots clients of the USARSim robot server may add to a
// running world with INIT, how many, and where. A front-end section: the scenario layer reads
// it, the robot server applies it (robot_server/spawn_policy.h), the simulation never sees it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "energy/energy_spec.h"
#include "net/network_spec.h"
#include "robots/node_model.h"
#include "sim/run_spec.h"

namespace sanet::sections {

// A robot class that clients may add (a USARSim class name, e.g. USARBot.P2DX) and the robot
// it becomes here.
struct SpawnClass {
  std::string usarsim_class;  // matched without regard to case, as Unreal's class names are
  robots::ModelSpec model;
  net::NodeRadio radio;
  std::optional<energy::EnergySpec> energy;
};

struct SpawnSpec {
  std::vector<SpawnClass> classes;
  std::size_t max = 8;  // robots added over the whole run
  // Where they may stand: min and max corners (DefaultSpawnRegion unless the scenario says).
  std::pair<Vec2, Vec2> region{{-1e6, -1e6}, {1e6, 1e6}};
};

// Whether two class names are the same class (Unreal's names ignore case).
bool SameClass(const std::string& a, const std::string& b);

// What a spawn section offers when it names no classes: USARSim's Pioneers as diffdrive robots
// with their laser, and sanet's own models under their names.
std::vector<SpawnClass> DefaultSpawnClasses();

// Where spawned robots may stand unless the scenario says: the field of `world_size` centred on
// the middle of the scenario's nodes and obstacles (min corner, max corner).
std::pair<Vec2, Vec2> DefaultSpawnRegion(const sim::RunSpec& spec);

}  // namespace sanet::sections
