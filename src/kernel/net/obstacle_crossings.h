// What stands between two antennas: the straight segment between them intersected with the
// world's static obstacles (walls and boxes with their heights and yaw), for the radio's
// obstacle loss (the multi-wall model of COST 231: a loss per obstacle crossed, and optionally a
// loss per metre inside it, as Veins' obstacle shadowing). The obstacles sit in a uniform grid
// seen from above; a segment visits only the cells it crosses (Amanatides and Woo's traversal),
// so a link costs what lies near it, not what the world holds, and no physics engine is asked
// (its ray casts would serialise the two-thread mode).
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "physics/physics_world.h"

namespace sanet::net {

struct RadioObstacle {
  physics::StaticBox box;    // centre (z: half way up), length, width, height, yaw
  double loss_db = 0;        // per crossing
  double loss_db_per_m = 0;  // inside it
  // A piece of a wall made of several boxes (a map's cells): a segment's crossings of pieces
  // whose gaps along it are at most `joined_within` m are one crossing of the wall, charged
  // `loss_db` once. false: every crossing is its own.
  bool piece = false;
  double joined_within = 0;
};

struct Crossing {
  std::size_t obstacle;  // index into the obstacles given
  double length;         // m of the segment inside it
};

// The part of segment a-b inside `box`, in m (0 if it misses, or only touches a face).
double LengthInside(const physics::StaticBox& box, const physics::Vec3& a, const physics::Vec3& b);
// The same as the fractions of a-b where it enters and leaves the box (enter >= leave: it misses).
std::pair<double, double> EnterLeave(const physics::StaticBox& box, const physics::Vec3& a, const physics::Vec3& b);

class ObstacleCrossings {
 public:
  // `cell`: the grid's cell side, m (about an obstacle's length suits).
  explicit ObstacleCrossings(std::vector<RadioObstacle> obstacles, double cell = 5.0);
  bool empty() const { return obstacles_.empty(); }
  std::size_t size() const { return obstacles_.size(); }
  // Every obstacle segment a-b passes through, in the order the obstacles were given.
  std::vector<Crossing> Crossings(const physics::Vec3& a, const physics::Vec3& b) const;
  // The multi-wall loss of a-b: each crossing's loss plus its loss per metre times its length
  // (a run of pieces one crossing).
  double LossDb(const physics::Vec3& a, const physics::Vec3& b) const;

 private:
  std::int64_t Cell(double v) const { return static_cast<std::int64_t>(std::floor((v - origin_) / cell_)); }
  void Visit(std::int64_t cx, std::int64_t cy, std::vector<std::size_t>& found) const;
  void Candidates(const physics::Vec3& a, const physics::Vec3& b, std::vector<std::size_t>& found) const;

  std::vector<RadioObstacle> obstacles_;
  double cell_, origin_ = 0;
  std::int64_t min_x_ = 0, min_y_ = 0, max_x_ = -1, max_y_ = -1;  // the cells that hold obstacles
  std::vector<std::vector<std::size_t>> cells_;                   // by (x - min_x) * rows + (y - min_y)
  mutable std::vector<std::uint32_t> seen_;                       // per obstacle: the query that saw it
  mutable std::uint32_t query_ = 0;
  mutable std::vector<std::size_t> found_;  // LossDb's scratch
  mutable std::vector<std::pair<double, double>> pieces_;
  static std::size_t Runs(std::vector<std::pair<double, double>>& pieces, double gap);
};

}  // namespace sanet::net
