// Where a scenario's nodes start: no body may start inside an obstacle or another body. ODE
// would report an internal error and leave the robot stuck for the whole run, and a robot put on
// a mote shoves it; both used to pass unnoticed. The check is certain, never a guess: it refuses
// only bodies whose inscribed circles (robots::InscribedRadius) meet an obstacle or each other,
// and names both with their lines. Bodies that may only touch are left to the run, which reports
// ODE's messages as warnings.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "sim/run_spec.h"

namespace sanet::scenario {

// Where a node was given in its file: the line and field an error names.
struct NodePlace {
  int line = 0;
  std::string field;  // "nodes[2].pose", or "nodes[3].grid" for a grid's nodes
};

// Throws ScenarioError at the later of two overlapping nodes (or at the node inside an
// obstacle), naming the other with its line. `obstacle_lines[i]` is world.obstacles[i]'s line.
void CheckPlacement(const std::string& file, const sim::RunSpec& run, const std::vector<NodePlace>& places,
                    const std::vector<int>& obstacle_lines);

// Room for one more body among a run's obstacles and the nodes it has so far: where a scatter
// item may put a node, by the same rule CheckPlacement holds them to.
class StartingRoom {
 public:
  explicit StartingRoom(const sim::RunSpec& run);
  bool Fits(Vec2 p, double radius) const;

 private:
  long long Cell(double v) const;
  const sim::RunSpec& run_;
  double widest_ = 0, cell_ = 1;
  std::unordered_map<long long, std::vector<NodeId>> cells_;
};

// Nodes far outside the field (the rectangle of world.size centred on the middle of the nodes
// and obstacles, which plots and spawning use): one warning, naming the farthest.
std::vector<std::string> FieldWarnings(const std::string& file, const sim::RunSpec& run,
                                       const std::vector<NodePlace>& places);

}  // namespace sanet::scenario
