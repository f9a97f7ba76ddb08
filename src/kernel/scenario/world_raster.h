// The scenario's world as an occupancy grid (for `sanet map`): every obstacle's footprint seen
// from above (a cell is occupied when its centre lies inside a box, walls and a map's boxes
// alike, whatever their height), everything else free, over the obstacles and nodes with a
// metre's margin. The grid is laid on the world's map's cells when the scenario has one of the
// same resolution, so that its cells come back as they were.
#pragma once

#include "scenario/ros_map.h"
#include "sim/run_spec.h"

namespace sanet::scenario {

OccupancyMap RasterizeWorld(const sim::RunSpec& spec, double resolution);

}  // namespace sanet::scenario
