#include "trace/figures.h"

#include <algorithm>
#include <cmath>

#include "trace/figure_svg.h"

namespace sanet::trace {
namespace {

using svg::Escape;
using svg::Num;
using svg::Short;

using svg::kColors;
constexpr const char* kMote = "#1a7f37";
constexpr const char* kObstacle = "#555555";

void Obstacles(std::ostringstream& s, const svg::Frame& f, const FigureInput& in) {
  for (const FigureObstacle& o : in.obstacles) {
    // Outlined as well, so that a thin wall stays visible on a large field.
    s << "<polygon fill=\"" << kObstacle << "\" stroke=\"" << kObstacle
      << "\" stroke-width=\"3\" stroke-linejoin=\"round\" points=\"";
    for (auto [u, v] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
      const Vec2 corner = Rotate({u * o.size.x / 2, v * o.size.y / 2}, o.yaw);
      s << f.Point(o.center.x + corner.x, o.center.y + corner.y) << " ";
    }
    s << "\"/>\n";
  }
}

// A mote that was pushed shows where it stood, hollow, and its way to where it ended.
void PushedMote(std::ostringstream& s, const svg::Frame& f, const FigureNode& n) {
  const Pose2D &a = n.start, &b = n.final_pose;
  if (!n.pushed) return;
  s << "<rect x=\"" << Num(f.X(a.x) - 3) << "\" y=\"" << Num(f.Y(a.y) - 3)
    << "\" width=\"6\" height=\"6\" fill=\"none\" stroke=\"" << kMote << "\"/>\n<line x1=\"" << Num(f.X(a.x))
    << "\" y1=\"" << Num(f.Y(a.y)) << "\" x2=\"" << Num(f.X(b.x)) << "\" y2=\"" << Num(f.Y(b.y)) << "\" stroke=\""
    << kMote << "\" stroke-dasharray=\"3,2\"/>\n";
}

void Motes(std::ostringstream& s, const svg::Frame& f, const FigureInput& in, svg::Labels& labels) {
  for (const FigureNode& n : in.nodes) {
    if (!n.mote) continue;
    PushedMote(s, f, n);
    const Pose2D& p = n.final_pose;
    s << "<rect x=\"" << Num(f.X(p.x) - 3) << "\" y=\"" << Num(f.Y(p.y) - 3) << "\" width=\"6\" height=\"6\" fill=\""
      << kMote << "\"/>\n";
    labels.Place(s, f.X(p.x) + 5, f.Y(p.y) - 5, n.name, 10, kMote);
  }
}

// Above this many tracks (a swarm) they are neither named nor their dots timed: the names would
// cover the paths, and the legend would run off the figure.
constexpr std::size_t kNamedTracks = 12;

// A track, a dot every `tick` seconds with its time where the label has room, its name at the
// start (both only for a `named` track).
void TrackWithTicks(std::ostringstream& s, const svg::Frame& f, const Track& t, const char* color, double tick,
                    svg::Labels& labels, bool named) {
  s << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.5\" points=\"";
  for (std::size_t i = 0; i < t.x.size(); ++i) s << f.Point(t.x[i], t.y[i]) << " ";
  s << "\"/>\n";
  if (!t.x.empty())  // the start, ringed: a robot that never moved is seen too
    s << "<circle cx=\"" << Num(f.X(t.x.front())) << "\" cy=\"" << Num(f.Y(t.y.front()))
      << "\" r=\"5\" fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.5\"/>\n";
  if (named && !t.x.empty())
    labels.Place(s, f.X(t.x.front()) + 6, f.Y(t.y.front()) + 14, t.node + " (start)", 12, color);
  double next_tick = tick;
  for (std::size_t i = 0; i < t.x.size(); ++i) {
    if (t.t[i] + 1e-9 < next_tick) continue;
    s << "<circle cx=\"" << Num(f.X(t.x[i])) << "\" cy=\"" << Num(f.Y(t.y[i])) << "\" r=\"3\" fill=\"" << color
      << "\"/>\n";
    if (named) labels.Place(s, f.X(t.x[i]) + 4, f.Y(t.y[i]) + 12, Short(next_tick) + " s", 9, color);
    while (next_tick <= t.t[i] + 1e-9) next_tick += tick;
  }
}

}  // namespace

std::string MapSvg(const FigureInput& in, double tick) {
  const svg::Frame f = svg::Frame::Around(in);
  std::ostringstream s;
  svg::Labels labels;
  f.Open(s, in.title + ": trajectories");
  Obstacles(s, f, in);
  Motes(s, f, in, labels);
  const bool named = in.tracks.size() <= kNamedTracks;
  for (std::size_t k = 0; k < in.tracks.size(); ++k)
    TrackWithTicks(s, f, in.tracks[k], kColors[k % 6], tick, labels, named);
  f.Axes(s);
  f.ScaleBar(s);
  svg::Legend legend(f);
  if (named)
    for (std::size_t k = 0; k < in.tracks.size(); ++k) legend.Line(s, kColors[k % 6], in.tracks[k].node);
  else
    legend.Line(s, kColors[0], std::to_string(in.tracks.size()) + " robots");
  legend.Dot(s, "#333333", "every " + Short(tick) + " s");
  if (std::any_of(in.nodes.begin(), in.nodes.end(), [](const FigureNode& n) { return n.mote; }))
    legend.Square(s, kMote, "mote");
  if (!in.obstacles.empty()) legend.Square(s, kObstacle, "obstacle");
  s << "</svg>\n";
  return s.str();
}

std::string PacketsSvg(const FigureInput& in) {
  const svg::Frame f = svg::Frame::Around(in);
  std::ostringstream s;
  svg::Labels labels;
  f.Open(s, in.title + ": IP packets received per node");
  Obstacles(s, f, in);
  const auto [few_it, most_it] = std::minmax_element(in.received.begin(), in.received.end());
  const double few = in.received.empty() ? 0 : *few_it, most = in.received.empty() ? 0 : *most_it;
  // Motes first, robots (where they ended, smaller) over them: a robot often ends on a mote.
  std::vector<std::size_t> order;
  for (bool motes : {true, false})
    for (std::size_t i = 0; i < in.nodes.size() && i < in.received.size(); ++i)
      if (in.nodes[i].mote == motes) order.push_back(i);
  for (std::size_t i : order) {
    const Pose2D& p = in.nodes[i].final_pose;
    const double share = most > few ? (in.received[i] - few) / (most - few) : 1;
    const bool mote = in.nodes[i].mote;
    s << "<circle cx=\"" << Num(f.X(p.x)) << "\" cy=\"" << Num(f.Y(p.y)) << "\" r=\"" << (mote ? 12 : 8) << "\" fill=\""
      << svg::ScaleColor(share) << "\" stroke=\"" << (mote ? "#333333" : "#d62728") << "\" stroke-width=\"1.5\"/>\n";
    labels.Place(s, f.X(p.x), f.Y(p.y) + 25, in.nodes[i].name + " " + std::to_string(in.received[i]), 10, "#222222",
                 "middle");
  }
  f.Axes(s);
  f.ScaleBar(s);
  svg::ColorBar(s, f.width() - svg::Frame::kRight + 20, svg::Frame::kTop + 24, few, most, "packets received");
  s << "</svg>\n";
  return s.str();
}

}  // namespace sanet::trace
