// The world as visualization_msgs markers, which RViz, Foxglove and Lichtblick draw in 3D: the
// obstacles (walls and boxes with their heights), the motes, each robot's body (in its own
// R/base_link frame, so that it moves with /tf) with its name above it, and the radio's frames
// as lines between the nodes that exchanged them.
#pragma once

#include <cstdint>
#include <vector>

#include "ros2msg/messages.h"
#include "sim/run_nodes.h"
#include "sim/run_spec.h"

namespace sanet::ros2_presentation {

// Everything that stands in the world at time `t` (stamped with it): obstacles, motes, bodies.
ros2msg::visualization_msgs::MarkerArray WorldMarkers(const sim::RunSpec& spec, const sim::RunNodes& nodes, double t);

// One frame the radio delivered, from where the sender stood to where the receiver stood;
// `data`: carrying applications' packets (unicast or broadcast), otherwise routing, ARP or
// management.
struct RadioLine {
  Vec2 from, to;
  bool data = false;
};
// The frames delivered in a window of `lifetime` s starting at `t`, as one line list for data
// frames and one for the others, which disappear when the window is over.
ros2msg::visualization_msgs::MarkerArray RadioMarkers(double t, double lifetime, const std::vector<RadioLine>& lines);

}  // namespace sanet::ros2_presentation
