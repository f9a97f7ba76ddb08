// A run's surroundings for its sensors (sensors/surroundings.h), from its world: the datum, and
// where no satellite fix is had: world.gnss_denied's regions, each building drawn by obstacles
// marked `indoor` (the convex hull of the indoor obstacles within a doorway of each other), and
// world.map's extent when the map is marked `indoor`.
#pragma once

#include <string>
#include <vector>

#include "sensors/surroundings.h"
#include "sim/run_spec.h"

namespace sanet::sim {

// m: indoor obstacles closer than this belong to one building (a door between two walls).
inline constexpr double kDoorway = 1.5;

sensors::Surroundings SurroundingsOf(const RunSpec& spec);
// Colours cameras see where the scenario gives none.
inline constexpr Rgb kObstacleColor{150, 150, 150}, kMapColor{180, 180, 170};
Rgb DefaultBodyColor(robots::ModelKind kind);
// A node's body as cameras see it, where it stands.
sensors::SceneBody SceneBodyOf(NodeId node, const robots::ModelSpec& model, const Pose2D& pose);

// For `sanet validate`: the datum and where there is no fix, the buildings of indoor obstacles by
// their hulls' corners; "" for a world with neither.
std::string DescribeSurroundings(const RunSpec& spec);

// The buildings that indoor obstacles make: the convex hull of each group of footprints within
// kDoorway of each other.
std::vector<sensors::Region> Buildings(const std::vector<Obstacle>& obstacles);

}  // namespace sanet::sim
