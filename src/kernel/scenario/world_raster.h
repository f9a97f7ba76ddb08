// The scenario's world as an occupancy grid (for `sanet map`): every obstacle's footprint seen
// from above (a cell is occupied when a box overlaps it at all, so that a wall thinner than a
// cell stays a wall; walls and a map's boxes alike, whatever their height), everything else free, over the obstacles
// and nodes with a metre's margin. The grid is laid on the world's map's cells when the scenario has one of the same
// resolution, so that its cells come back as they were.
#pragma once

#include "scenario/ros_map.h"
#include "sim/run_spec.h"

namespace sanet::scenario {

// Throws std::invalid_argument for a grid of more than 400 million cells (before making it).
OccupancyMap RasterizeWorld(const sim::RunSpec& spec, double resolution);

}  // namespace sanet::scenario
