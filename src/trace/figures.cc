#include "trace/figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace sanet::trace {
namespace {

constexpr double kWidth = 800;  // px
constexpr const char* kColors[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

std::string Num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f", v);
  return s;
}

std::string Escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

// World metres to picture pixels, y up, with a margin around everything drawn.
class Frame {
 public:
  explicit Frame(const FigureInput& in) {
    auto grow = [&](double x, double y) {
      x0_ = std::min(x0_, x), x1_ = std::max(x1_, x), y0_ = std::min(y0_, y), y1_ = std::max(y1_, y);
    };
    for (const FigureNode& n : in.nodes) grow(n.final_pose.x, n.final_pose.y), grow(n.start.x, n.start.y);
    for (const Track& t : in.tracks)
      for (std::size_t i = 0; i < t.x.size(); ++i) grow(t.x[i], t.y[i]);
    for (const FigureObstacle& o : in.obstacles) {
      const double r = std::hypot(o.size.x, o.size.y) / 2;
      grow(o.center.x - r, o.center.y - r);
      grow(o.center.x + r, o.center.y + r);
    }
    const double pad = 0.06 * std::max({x1_ - x0_, y1_ - y0_, 1.0});
    x0_ -= pad, x1_ += pad, y0_ -= pad, y1_ += pad;
    scale_ = kWidth / (x1_ - x0_);
  }
  double X(double x) const { return (x - x0_) * scale_; }
  double Y(double y) const { return (y1_ - y) * scale_; }
  double height() const { return (y1_ - y0_) * scale_; }
  double scale() const { return scale_; }
  std::string Point(double x, double y) const { return Num(X(x)) + "," + Num(Y(y)); }

 private:
  double x0_ = 1e300, x1_ = -1e300, y0_ = 1e300, y1_ = -1e300, scale_ = 1;
};

std::string Header(const Frame& f, const std::string& title) {
  std::ostringstream s;
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Num(kWidth) << "\" height=\"" << Num(f.height() + 40)
    << "\" viewBox=\"0 -40 " << Num(kWidth) << " " << Num(f.height() + 40) << "\" font-family=\"sans-serif\">\n"
    << "<title>" << Escape(title) << "</title>\n"
    << "<rect x=\"0\" y=\"0\" width=\"" << Num(kWidth) << "\" height=\"" << Num(f.height())
    << "\" fill=\"#fafafa\" stroke=\"#999\"/>\n"
    << "<text x=\"8\" y=\"-14\" font-size=\"16\">" << Escape(title) << "</text>\n";
  return s.str();
}

void Obstacles(std::ostringstream& s, const Frame& f, const FigureInput& in) {
  for (const FigureObstacle& o : in.obstacles) {
    // Outlined as well, so that a thin wall stays visible on a large field.
    s << "<polygon fill=\"#555\" stroke=\"#555\" stroke-width=\"3\" stroke-linejoin=\"round\" points=\"";
    for (auto [u, v] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
      const Vec2 corner = Rotate({u * o.size.x / 2, v * o.size.y / 2}, o.yaw);
      s << f.Point(o.center.x + corner.x, o.center.y + corner.y) << " ";
    }
    s << "\"><title>" << o.kind << "</title></polygon>\n";
  }
}

// A scale bar of a round length in the bottom-left corner.
void ScaleBar(std::ostringstream& s, const Frame& f) {
  double metres = std::pow(10.0, std::floor(std::log10(150 / f.scale())));
  if (metres * f.scale() < 60) metres *= 5;
  const double y = f.height() - 12;
  s << "<line x1=\"12\" y1=\"" << Num(y) << "\" x2=\"" << Num(12 + metres * f.scale()) << "\" y2=\"" << Num(y)
    << "\" stroke=\"#000\" stroke-width=\"2\"/><text x=\"12\" y=\"" << Num(y - 5) << "\" font-size=\"11\">"
    << Num(metres) << " m</text>\n";
}

}  // namespace

std::string MapSvg(const FigureInput& in, double tick) {
  const Frame f(in);
  std::ostringstream s;
  s << Header(f, in.title + ": trajectories (a mark every " + Num(tick) + " s)");
  Obstacles(s, f, in);
  for (std::size_t i = 0; i < in.nodes.size(); ++i) {
    if (!in.nodes[i].mote) continue;
    const Pose2D& p = in.nodes[i].final_pose;
    s << "<rect x=\"" << Num(f.X(p.x) - 3) << "\" y=\"" << Num(f.Y(p.y) - 3)
      << "\" width=\"6\" height=\"6\" fill=\"#1a7f37\"/><text x=\"" << Num(f.X(p.x) + 5) << "\" y=\""
      << Num(f.Y(p.y) - 5) << "\" font-size=\"10\" fill=\"#1a7f37\">" << Escape(in.nodes[i].name) << "</text>\n";
  }
  for (std::size_t k = 0; k < in.tracks.size(); ++k) {
    const Track& t = in.tracks[k];
    const char* color = kColors[k % 6];
    s << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.5\" points=\"";
    for (std::size_t i = 0; i < t.x.size(); ++i) s << f.Point(t.x[i], t.y[i]) << " ";
    s << "\"><title>" << Escape(t.node) << "</title></polyline>\n";
    double next_tick = tick;
    for (std::size_t i = 0; i < t.x.size(); ++i) {
      if (t.t[i] + 1e-9 < next_tick) continue;
      s << "<circle cx=\"" << Num(f.X(t.x[i])) << "\" cy=\"" << Num(f.Y(t.y[i])) << "\" r=\"3\" fill=\"" << color
        << "\"/><text x=\"" << Num(f.X(t.x[i]) + 4) << "\" y=\"" << Num(f.Y(t.y[i]) + 12)
        << "\" font-size=\"9\" fill=\"" << color << "\">" << Num(next_tick).substr(0, Num(next_tick).size() - 2)
        << " s</text>\n";
      while (next_tick <= t.t[i] + 1e-9) next_tick += tick;
    }
    if (!t.x.empty())
      s << "<text x=\"" << Num(f.X(t.x.front()) + 6) << "\" y=\"" << Num(f.Y(t.y.front()) + 4)
        << "\" font-size=\"12\" fill=\"" << color << "\">" << Escape(t.node) << " (start)</text>\n";
  }
  ScaleBar(s, f);
  s << "</svg>\n";
  return s.str();
}

std::string PacketsSvg(const FigureInput& in) {
  const Frame f(in);
  std::ostringstream s;
  s << Header(f, in.title + ": packets received per node (darker = more)");
  Obstacles(s, f, in);
  // Shades span the range received, from the fewest (light) to the most (dark).
  const auto [few_it, most_it] = std::minmax_element(in.received.begin(), in.received.end());
  const double few = in.received.empty() ? 0 : *few_it, most = in.received.empty() ? 0 : *most_it;
  for (std::size_t i = 0; i < in.nodes.size() && i < in.received.size(); ++i) {
    const Pose2D& p = in.nodes[i].final_pose;
    const double share = most > few ? (in.received[i] - few) / (most - few) : 1;
    const int level = static_cast<int>(std::lround(235 - 200 * share));
    char fill[16];
    std::snprintf(fill, sizeof fill, "#%02x%02x%02x", level, level, level);
    const bool mote = in.nodes[i].mote;
    s << "<circle cx=\"" << Num(f.X(p.x)) << "\" cy=\"" << Num(f.Y(p.y)) << "\" r=\"" << (mote ? 14 : 9) << "\" fill=\""
      << fill << "\" stroke=\"" << (mote ? "#333" : "#d62728") << "\"><title>" << Escape(in.nodes[i].name) << ": "
      << in.received[i] << " packets</title></circle>\n"
      << "<text x=\"" << Num(f.X(p.x)) << "\" y=\"" << Num(f.Y(p.y) + 26)
      << "\" font-size=\"10\" text-anchor=\"middle\">" << Escape(in.nodes[i].name) << " " << in.received[i]
      << "</text>\n";
    if (!mote) s << "<!-- robots are drawn where they ended -->\n";
  }
  ScaleBar(s, f);
  s << "</svg>\n";
  return s.str();
}

}  // namespace sanet::trace

namespace sanet::trace {

std::string LineSvg(const std::string& title, const std::string& x_label, const std::string& y_label,
                    const std::vector<std::pair<double, double>>& points, double reference) {
  const double w = 800, h = 360, left = 60, bottom = 40, top = 40, right = 20;
  double x0 = 0, x1 = 1, y1 = std::max(reference * 1.3, 1e-6);
  for (const auto& [x, y] : points) x1 = std::max(x1, x), y1 = std::max(y1, y);
  y1 *= 1.05;
  const auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * (w - left - right); };
  const auto py = [&](double y) { return h - bottom - y / y1 * (h - top - bottom); };
  std::ostringstream s;
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w
    << "\" height=\"" << h << "\" font-family=\"sans-serif\">\n<title>" << Escape(title) << "</title>\n"
    << "<rect width=\"" << w << "\" height=\"" << h << "\" fill=\"#fff\"/>\n"
    << "<text x=\"8\" y=\"22\" font-size=\"16\">" << Escape(title) << "</text>\n"
    << "<line x1=\"" << left << "\" y1=\"" << h - bottom << "\" x2=\"" << w - right << "\" y2=\"" << h - bottom
    << "\" stroke=\"#000\"/><line x1=\"" << left << "\" y1=\"" << top << "\" x2=\"" << left << "\" y2=\"" << h - bottom
    << "\" stroke=\"#000\"/>\n";
  for (int i = 0; i <= 5; ++i) {
    const double xv = x0 + (x1 - x0) * i / 5, yv = y1 * i / 5;
    s << "<text x=\"" << Num(px(xv)) << "\" y=\"" << h - bottom + 16 << "\" font-size=\"11\" text-anchor=\"middle\">"
      << Num(xv) << "</text><text x=\"" << left - 6 << "\" y=\"" << Num(py(yv) + 4)
      << "\" font-size=\"11\" text-anchor=\"end\">" << Num(yv) << "</text>\n";
  }
  s << "<text x=\"" << Num((left + w - right) / 2) << "\" y=\"" << h - 6
    << "\" font-size=\"12\" text-anchor=\"middle\">" << Escape(x_label) << "</text><text x=\"14\" y=\"" << Num(top + 10)
    << "\" font-size=\"12\">" << Escape(y_label) << "</text>\n";
  if (reference > 0)
    s << "<line x1=\"" << left << "\" x2=\"" << w - right << "\" y1=\"" << Num(py(reference)) << "\" y2=\""
      << Num(py(reference)) << "\" stroke=\"#888\" stroke-dasharray=\"6,4\"/><text x=\"" << w - right - 4 << "\" y=\""
      << Num(py(reference) - 4) << "\" font-size=\"11\" text-anchor=\"end\" fill=\"#555\">" << Num(reference)
      << " m</text>\n";
  s << "<polyline fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"1.2\" points=\"";
  for (const auto& [x, y] : points) s << Num(px(x)) << "," << Num(py(y)) << " ";
  s << "\"/>\n</svg>\n";
  return s.str();
}

}  // namespace sanet::trace
