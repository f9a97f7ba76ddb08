#include "sim/radio_walls.h"

#include <algorithm>

#include "net/wall_materials.h"

namespace sanet::sim {

double RadioThickness(const Obstacle& obstacle) {
  return obstacle.kind == "wall" ? obstacle.box.size.y : std::min(obstacle.box.size.x, obstacle.box.size.y);
}

std::vector<net::RadioObstacle> RadioWalls(const RunSpec& spec) {
  return spec.network ? RadioWalls(spec, net::FrequencyHz(spec.network->standard)) : std::vector<net::RadioObstacle>{};
}

std::vector<net::RadioObstacle> RadioWalls(const RunSpec& spec, double frequency) {
  std::vector<net::RadioObstacle> walls;
  if (!spec.network) return walls;
  for (const Obstacle& o : spec.obstacles) {
    if (o.from_map && spec.map) {  // a run of the map's boxes is one wall `thickness` thick
      const double loss =
          net::SlabLossDb(o.material.value_or(spec.obstacle_material), spec.map->wall_thickness, frequency);
      if (loss > 0) walls.push_back({o.box, loss, 0, true, spec.map->resolution / 2});
      continue;
    }
    const double loss = o.radio_loss_db.value_or(
        net::SlabLossDb(o.material.value_or(spec.obstacle_material), RadioThickness(o), frequency));
    if (loss > 0 || o.radio_loss_db_per_m > 0) walls.push_back({o.box, loss, o.radio_loss_db_per_m});
  }
  return walls;
}

}  // namespace sanet::sim
