// world.map: a building from a ROS map (scenario/ros_map.h). Its blocked cells (occupied, and
// unknown ones with `unknown: blocked`) merged into boxes (scenario/map_boxes.h) become static
// obstacles `height` tall, of the map's radio `material`, in the map's frame, which is the
// world's: a robot at [x, y] stands where the map's pixel at (x, y) is. The effective scenario
// prints the boxes in cells with the map's resolution and origin, so it runs without the files.
#pragma once

#include "scenario/fields.h"
#include "sim/run_spec.h"

namespace sanet::scenario {

void AddWorldMap(Fields<sim::RunSpec>& fields);

// The map's boxes as obstacles (appended to the run's, marked from_map).
void AppendMapObstacles(const sim::WorldMap& map, std::vector<sim::Obstacle>& obstacles);

}  // namespace sanet::scenario
