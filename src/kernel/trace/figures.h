// Figures of a run as SVG files that browsers, rsvg-convert and ImageMagick draw alike: the map
// (obstacles, motes, trajectories with a mark every `tick` seconds), the packets map (each node a
// disc coloured by the packets it received, with a colour scale), trajectories over time, and a
// time series. Maps have axes in metres, a scale bar and a legend; labels never overlap.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sanet/geometry.h"

namespace sanet::trace {

struct Track {
  std::string node;
  std::vector<double> t, x, y;
};

// What the figures draw, in world metres; the writers know nothing of how a run is described.
struct FigureObstacle {
  std::string kind;  // "box", "wall" or "map" (a box of world.map), the tooltip
  Vec2 center, size;
  double yaw = 0;
};

struct FigureNode {
  std::string name;
  bool mote = false;
  Pose2D start, final_pose;
  bool pushed = false;  // a mote that robots pushed away (the run warns of it): drawn with its way
};

struct FigureInput {
  std::string title;  // the run's name
  std::vector<FigureObstacle> obstacles;
  std::vector<FigureNode> nodes;
  std::vector<Track> tracks;            // of the nodes that moved
  std::vector<std::uint64_t> received;  // per node, empty without a network
};

std::string MapSvg(const FigureInput& in, double tick);
std::string PacketsSvg(const FigureInput& in);
// Named time series as lines of their own colours, with a legend.
struct Series {
  std::string name;
  std::vector<std::pair<double, double>> points;
};
// A stretch of the x axis shaded and named (a link curve's regions), under the lines.
struct Band {
  double from, to;
  std::string name;
  const char* fill;
};
std::string LinesSvg(const std::string& title, const std::string& x_label, const std::string& y_label,
                     const std::vector<Series>& series, const std::vector<Band>& bands = {});
// A time series as a line, with a dashed horizontal reference line when `reference` > 0.
std::string LineSvg(const std::string& title, const std::string& x_label, const std::string& y_label,
                    const std::vector<std::pair<double, double>>& points, double reference);

}  // namespace sanet::trace
