// The figures that are plots rather than maps: time series.
#include <algorithm>
#include <cmath>

#include "trace/figure_svg.h"
#include "trace/figures.h"

namespace sanet::trace {
namespace {

using svg::Escape;
using svg::Num;
using svg::Short;

using svg::kColors;

void Document(std::ostringstream& s, double w, double h, const std::string& title) {
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w
    << "\" height=\"" << h << "\" viewBox=\"0 0 " << w << " " << h
    << "\" font-family=\"DejaVu Sans, sans-serif\">\n<title>" << Escape(title) << "</title>\n<rect width=\"" << w
    << "\" height=\"" << h << "\" fill=\"#ffffff\"/>\n<text x=\"8\" y=\"22\" font-size=\"16\">" << Escape(title)
    << "</text>\n";
}

}  // namespace

namespace {

struct Plot {
  double w = 800, h = 360, left = 60, bottom = 44, top = 40, right = 20;
  double x1 = 1, y1 = 1e-6;
  double px(double x) const { return left + x / x1 * (w - left - right); }
  double py(double y) const { return h - bottom - y / y1 * (h - top - bottom); }
};

// The frame, the ticks and the labels of a plot whose axes start at zero.
void Axes(std::ostringstream& s, const Plot& p, const std::string& x_label, const std::string& y_label) {
  s << "<line x1=\"" << p.left << "\" y1=\"" << p.h - p.bottom << "\" x2=\"" << p.w - p.right << "\" y2=\""
    << p.h - p.bottom << "\" stroke=\"#000000\"/><line x1=\"" << p.left << "\" y1=\"" << p.top << "\" x2=\"" << p.left
    << "\" y2=\"" << p.h - p.bottom << "\" stroke=\"#000000\"/>\n";
  const double xs = svg::NiceStep(p.x1, 6), ys = svg::NiceStep(p.y1, 5);
  for (double x = 0; x <= p.x1 + 1e-9; x += xs)
    s << "<text x=\"" << Num(p.px(x)) << "\" y=\"" << p.h - p.bottom + 16
      << "\" font-size=\"11\" text-anchor=\"middle\">" << Short(x) << "</text>\n";
  for (double y = 0; y <= p.y1 + 1e-9; y += ys)
    s << "<text x=\"" << p.left - 6 << "\" y=\"" << Num(p.py(y) + 4) << "\" font-size=\"11\" text-anchor=\"end\">"
      << Short(y) << "</text>\n";
  s << "<text x=\"" << Num((p.left + p.w - p.right) / 2) << "\" y=\"" << p.h - 8
    << "\" font-size=\"12\" text-anchor=\"middle\">" << Escape(x_label) << "</text><text x=\"" << p.left + 6
    << "\" y=\"" << p.top - 4 << "\" font-size=\"12\">" << Escape(y_label) << "</text>\n";
}

void Polyline(std::ostringstream& s, const Plot& p, const std::vector<std::pair<double, double>>& points,
              const std::string& colour) {
  s << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.2\" points=\"";
  for (const auto& [x, y] : points) s << Num(p.px(x)) << "," << Num(p.py(y)) << " ";
  s << "\"/>\n";
}

using Points = std::vector<std::pair<double, double>>;

Plot Fit(const std::vector<const Points*>& all, double y_at_least) {
  Plot p;
  p.y1 = std::max(y_at_least, 1e-6);
  for (const auto* points : all)
    for (const auto& [x, y] : *points) p.x1 = std::max(p.x1, x), p.y1 = std::max(p.y1, y);
  p.y1 *= 1.05;
  return p;
}

}  // namespace

namespace {

// Shaded under everything, named along the bottom of the plot (a name that would overlap
// another is left out: a narrow band says nothing).
void Bands(std::ostringstream& s, const Plot& p, const std::vector<Band>& bands) {
  svg::Labels names;
  for (const Band& band : bands) {
    const double x0 = p.px(std::max(0.0, band.from)), x1 = p.px(std::min(p.x1, band.to));
    if (x1 <= x0) continue;
    s << "<rect x=\"" << Num(x0) << "\" y=\"" << p.top << "\" width=\"" << Num(x1 - x0) << "\" height=\""
      << p.h - p.top - p.bottom << "\" fill=\"" << band.fill << "\" fill-opacity=\"0.35\"/>\n";
    names.Place(s, 0.5 * (x0 + x1), p.h - p.bottom - 6, band.name, 11, "#555555", "middle");
  }
}

}  // namespace

std::string LinesSvg(const std::string& title, const std::string& x_label, const std::string& y_label,
                     const std::vector<Series>& series, const std::vector<Band>& bands) {
  std::vector<const Points*> all;
  for (const Series& one : series) all.push_back(&one.points);
  const Plot p = Fit(all, 0);
  std::ostringstream s;
  Document(s, p.w, p.h, title);
  Bands(s, p, bands);
  Axes(s, p, x_label, y_label);
  for (std::size_t i = 0; i < series.size(); ++i) {
    const std::string colour = kColors[i % std::size(kColors)];
    Polyline(s, p, series[i].points, colour);
    s << "<text x=\"" << p.w - p.right - 4 << "\" y=\"" << p.top + 14 * i << "\" font-size=\"11\" "
      << "text-anchor=\"end\" fill=\"" << colour << "\">" << Escape(series[i].name) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

std::string LineSvg(const std::string& title, const std::string& x_label, const std::string& y_label,
                    const std::vector<std::pair<double, double>>& points, double reference) {
  const Plot p = Fit({&points}, reference * 1.3);
  std::ostringstream s;
  Document(s, p.w, p.h, title);
  Axes(s, p, x_label, y_label);
  if (reference > 0)
    s << "<line x1=\"" << p.left << "\" x2=\"" << p.w - p.right << "\" y1=\"" << Num(p.py(reference)) << "\" y2=\""
      << Num(p.py(reference)) << "\" stroke=\"#888888\" stroke-dasharray=\"6,4\"/><text x=\"" << p.w - p.right - 4
      << "\" y=\"" << Num(p.py(reference) - 4) << "\" font-size=\"11\" text-anchor=\"end\" fill=\"#555555\">reference "
      << Short(reference) << " m</text>\n";
  Polyline(s, p, points, "#1f77b4");
  s << "</svg>\n";
  return s.str();
}

}  // namespace sanet::trace
