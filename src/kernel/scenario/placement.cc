#include "scenario/placement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "core/metres.h"
#include "scenario/yaml_reader.h"
#include "sections/spawn_section.h"

namespace sanet::scenario {
namespace {

// A cell of a grid over the ground (CheckPairs', StartingRoom's) as one hash key.
long long CellKey(long long cx, long long cy) { return cx * 4000003LL + cy; }

std::string At(const sim::NodeSpec& n) { return n.name + " at (" + Metres(n.pose.x) + ", " + Metres(n.pose.y) + ")"; }

// "world.obstacles[2], a wall (line 9)", or a box of world.map's.
std::string ObstacleNamed(const sim::RunSpec& run, std::size_t i, const std::vector<int>& obstacle_lines) {
  const sim::Obstacle& o = run.obstacles[i];
  if (!o.from_map)
    return "world.obstacles[" + std::to_string(i) + "], a " + o.kind + " (line " +
           std::to_string(obstacle_lines.at(i)) + ")";
  const double hx = o.box.size.x / 2, hy = o.box.size.y / 2;
  return "a wall of world.map " + run.map->file + " (its box from (" + Metres(o.box.center.x - hx) + ", " +
         Metres(o.box.center.y - hy) + ") to (" + Metres(o.box.center.x + hx) + ", " + Metres(o.box.center.y + hy) +
         ") m" + (o.box.yaw != 0 ? " in the map's turned frame" : "") + ")";
}

void CheckObstacles(const std::string& file, const sim::RunSpec& run, const std::vector<NodePlace>& places,
                    const std::vector<int>& obstacle_lines) {
  for (NodeId id = 0; id < run.nodes.size(); ++id) {
    const sim::NodeSpec& n = run.nodes[id];
    const double radius = robots::InscribedRadius(n.model);
    for (std::size_t i = 0; i < run.obstacles.size(); ++i) {
      const double gap = physics::DistanceFromAbove(n.pose.position(), run.obstacles[i].box);
      if (gap >= radius) continue;
      const std::string what = run.obstacles[i].from_map ? "wall" : run.obstacles[i].kind;
      throw ScenarioError(
          file, places[id].line, places[id].field,
          At(n) + " is inside " + ObstacleNamed(run, i, obstacle_lines) + ": its body reaches " + Metres(radius) +
              " m around its pose, and " +
              (gap > 0 ? "the " + what + " is " + Metres(gap) + " m away" : "its pose is inside the " + what) +
              "; move one of them");
    }
  }
}

// Pairs within reach of each other, found through a grid of cells as wide as the largest reach.
void CheckPairs(const std::string& file, const sim::RunSpec& run, const std::vector<NodePlace>& places) {
  std::vector<double> radius(run.nodes.size());
  double widest = 0;
  for (NodeId id = 0; id < run.nodes.size(); ++id)
    widest = std::max(widest, radius[id] = robots::InscribedRadius(run.nodes[id].model));
  const double cell = std::max(2 * widest, 1e-3);
  std::unordered_map<long long, std::vector<NodeId>> cells;
  for (NodeId id = 0; id < run.nodes.size(); ++id) {
    const sim::NodeSpec& n = run.nodes[id];
    const long long cx = std::llround(std::floor(n.pose.x / cell)), cy = std::llround(std::floor(n.pose.y / cell));
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto near = cells.find(CellKey(cx + dx, cy + dy));
        if (near == cells.end()) continue;
        for (NodeId other : near->second) {
          const double gap = Norm(run.nodes[other].pose.position() - n.pose.position());
          if (gap >= radius[id] + radius[other]) continue;
          throw ScenarioError(file, places[id].line, places[id].field,
                              At(n) + " overlaps " + At(run.nodes[other]) + " (line " +
                                  std::to_string(places[other].line) + "): their bodies reach " + Metres(radius[id]) +
                                  " and " + Metres(radius[other]) + " m around their poses, which are " + Metres(gap) +
                                  " m apart; move one of them");
        }
      }
    cells[CellKey(cx, cy)].push_back(id);
  }
}

}  // namespace

void CheckPlacement(const std::string& file, const sim::RunSpec& run, const std::vector<NodePlace>& places,
                    const std::vector<int>& obstacle_lines) {
  CheckObstacles(file, run, places, obstacle_lines);
  CheckPairs(file, run, places);
}

StartingRoom::StartingRoom(const sim::RunSpec& run) : run_(run) {
  for (const sim::NodeSpec& n : run.nodes) widest_ = std::max(widest_, robots::InscribedRadius(n.model));
  cell_ = std::max(2 * widest_, 1e-3);
  for (NodeId id = 0; id < run.nodes.size(); ++id)
    cells_[CellKey(Cell(run.nodes[id].pose.x), Cell(run.nodes[id].pose.y))].push_back(id);
}

long long StartingRoom::Cell(double v) const { return std::llround(std::floor(v / cell_)); }

bool StartingRoom::Fits(Vec2 p, double radius) const {
  for (const sim::Obstacle& o : run_.obstacles)
    if (physics::DistanceFromAbove(p, o.box) < radius) return false;
  const long long reach = static_cast<long long>(std::ceil((radius + widest_) / cell_));
  const long long cx = Cell(p.x), cy = Cell(p.y);
  for (long long dx = -reach; dx <= reach; ++dx)
    for (long long dy = -reach; dy <= reach; ++dy) {
      const auto near = cells_.find(CellKey(cx + dx, cy + dy));
      if (near == cells_.end()) continue;
      for (NodeId other : near->second) {
        const sim::NodeSpec& n = run_.nodes[other];
        if (Norm(n.pose.position() - p) < radius + robots::InscribedRadius(n.model)) return false;
      }
    }
  return true;
}

std::vector<std::string> FieldWarnings(const std::string& file, const sim::RunSpec& run,
                                       const std::vector<NodePlace>& places) {
  // Centred on the nodes' median, not their middle, so that one node far away is the one named.
  std::vector<double> xs, ys;
  for (const sim::NodeSpec& n : run.nodes) xs.push_back(n.pose.x), ys.push_back(n.pose.y);
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  std::nth_element(ys.begin(), ys.begin() + ys.size() / 2, ys.end());
  const Vec2 centre{xs[xs.size() / 2], ys[ys.size() / 2]};
  const Vec2 margin = run.world_size * 0.5;  // "far": more than half the field beyond its edge
  const Vec2 low = centre - margin, high = centre + margin;
  NodeId farthest = 0;
  double worst = 0;
  std::size_t outside = 0;
  for (NodeId id = 0; id < run.nodes.size(); ++id) {
    const Vec2 p = run.nodes[id].pose.position();
    const double beyond_x = std::max(low.x - p.x, p.x - high.x), beyond_y = std::max(low.y - p.y, p.y - high.y);
    if (beyond_x <= margin.x && beyond_y <= margin.y) continue;
    const double beyond = std::max(beyond_x, beyond_y);
    ++outside;
    if (beyond > worst) worst = beyond, farthest = id;
  }
  if (outside == 0) return {};
  return {ScenarioError(file, places[farthest].line, places[farthest].field,
                        std::to_string(outside) + (outside == 1 ? " node lies" : " nodes lie") +
                            " far outside the field of world.size (" + Metres(run.world_size.x) + " x " +
                            Metres(run.world_size.y) + " m around the nodes), " + At(run.nodes[farthest]) +
                            (outside == 1 ? ", " : " the farthest, ") + Metres(worst) +
                            " m beyond it: spawn.region and the viewer's ground use the field; give world.size the "
                            "extent of the scenario")
              .what()};
}

}  // namespace sanet::scenario
