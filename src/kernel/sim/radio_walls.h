// The scenario's obstacles as the radio sees them: each one's loss per crossing (its explicit
// `radio_loss_db`, or its material's slab loss at its thickness and the network's frequency) and
// per metre inside it. Obstacles that cost nothing are left out, so a world of `none` has no walls.
#pragma once

#include <vector>

#include "net/obstacle_crossings.h"
#include "sim/run_spec.h"

namespace sanet::sim {

// A wall's thickness is its width; a box's, the shorter of its sides seen from above.
double RadioThickness(const Obstacle& obstacle);
std::vector<net::RadioObstacle> RadioWalls(const RunSpec& spec);  // at the 802.11 standard's frequency
std::vector<net::RadioObstacle> RadioWalls(const RunSpec& spec, double frequency_hz);  // at another band

}  // namespace sanet::sim
