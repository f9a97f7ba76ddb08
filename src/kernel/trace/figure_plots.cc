// The figures that are plots rather than maps: a time series.
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

std::string LineSvg(const std::string& title, const std::string& x_label, const std::string& y_label,
                    const std::vector<std::pair<double, double>>& points, double reference) {
  const double w = 800, h = 360, left = 60, bottom = 44, top = 40, right = 20;
  double x1 = 1, y1 = std::max(reference * 1.3, 1e-6);
  for (const auto& [x, y] : points) x1 = std::max(x1, x), y1 = std::max(y1, y);
  y1 *= 1.05;
  const auto px = [&](double x) { return left + x / x1 * (w - left - right); };
  const auto py = [&](double y) { return h - bottom - y / y1 * (h - top - bottom); };
  std::ostringstream s;
  Document(s, w, h, title);
  s << "<line x1=\"" << left << "\" y1=\"" << h - bottom << "\" x2=\"" << w - right << "\" y2=\"" << h - bottom
    << "\" stroke=\"#000000\"/><line x1=\"" << left << "\" y1=\"" << top << "\" x2=\"" << left << "\" y2=\""
    << h - bottom << "\" stroke=\"#000000\"/>\n";
  const double xs = svg::NiceStep(x1, 6), ys = svg::NiceStep(y1, 5);
  for (double x = 0; x <= x1 + 1e-9; x += xs)
    s << "<text x=\"" << Num(px(x)) << "\" y=\"" << h - bottom + 16 << "\" font-size=\"11\" text-anchor=\"middle\">"
      << Short(x) << "</text>\n";
  for (double y = 0; y <= y1 + 1e-9; y += ys)
    s << "<text x=\"" << left - 6 << "\" y=\"" << Num(py(y) + 4) << "\" font-size=\"11\" text-anchor=\"end\">"
      << Short(y) << "</text>\n";
  s << "<text x=\"" << Num((left + w - right) / 2) << "\" y=\"" << h - 8
    << "\" font-size=\"12\" text-anchor=\"middle\">" << Escape(x_label) << "</text><text x=\"" << left + 6 << "\" y=\""
    << top - 4 << "\" font-size=\"12\">" << Escape(y_label) << "</text>\n";
  if (reference > 0)
    s << "<line x1=\"" << left << "\" x2=\"" << w - right << "\" y1=\"" << Num(py(reference)) << "\" y2=\""
      << Num(py(reference)) << "\" stroke=\"#888888\" stroke-dasharray=\"6,4\"/><text x=\"" << w - right - 4
      << "\" y=\"" << Num(py(reference) - 4) << "\" font-size=\"11\" text-anchor=\"end\" fill=\"#555555\">reference "
      << Short(reference) << " m</text>\n";
  s << "<polyline fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"1.2\" points=\"";
  for (const auto& [x, y] : points) s << Num(px(x)) << "," << Num(py(y)) << " ";
  s << "\"/>\n</svg>\n";
  return s.str();
}

}  // namespace sanet::trace
