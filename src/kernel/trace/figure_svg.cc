#include "trace/figure_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sanet::trace::svg {

std::string Num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f", v);
  return s;
}

std::string Short(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", std::fabs(v) < 1e-9 ? 0.0 : v);
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

double NiceStep(double span, int count) {
  const double raw = std::max(span, 1e-9) / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10 * power;
}

Frame::Frame(double x0, double x1, double y0, double y1) : x0_(x0), x1_(x1), y0_(y0), y1_(y1) {
  scale_ = kPlotWidth / std::max(x1_ - x0_, 1e-9);
}

Frame Frame::Around(const FigureInput& in) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  const auto grow = [&](double x, double y) {
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  };
  for (const FigureNode& n : in.nodes) grow(n.final_pose.x, n.final_pose.y), grow(n.start.x, n.start.y);
  for (const Track& t : in.tracks)
    for (std::size_t i = 0; i < t.x.size(); ++i) grow(t.x[i], t.y[i]);
  for (const FigureObstacle& o : in.obstacles)  // its corners: a long wall widens only its own way
    for (auto [u, v] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
      const Vec2 corner = Rotate({u * o.size.x / 2, v * o.size.y / 2}, o.yaw);
      grow(o.center.x + corner.x, o.center.y + corner.y);
    }
  const double pad = 0.06 * std::max({x1 - x0, y1 - y0, 1.0});
  return Frame(x0 - pad, x1 + pad, y0 - pad, y1 + pad);
}

void Frame::Open(std::ostringstream& s, const std::string& title) const {
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Num(width())
    << "\" height=\"" << Num(height()) << "\" viewBox=\"0 0 " << Num(width()) << " " << Num(height())
    << "\" font-family=\"DejaVu Sans, sans-serif\">\n<title>" << Escape(title) << "</title>\n"
    << "<rect x=\"0\" y=\"0\" width=\"" << Num(width()) << "\" height=\"" << Num(height()) << "\" fill=\"#ffffff\"/>\n"
    << "<rect x=\"" << Num(kLeft) << "\" y=\"" << Num(kTop) << "\" width=\"" << Num(kPlotWidth) << "\" height=\""
    << Num(height() - kTop - kBottom) << "\" fill=\"#fafafa\" stroke=\"#999999\"/>\n"
    << "<text x=\"8\" y=\"26\" font-size=\"16\">" << Escape(title) << "</text>\n";
}

void Frame::Axes(std::ostringstream& s) const {
  const double step = NiceStep(x1_ - x0_, 8);
  const double bottom = height() - kBottom;
  for (double x = std::ceil(x0_ / step) * step; x <= x1_; x += step)
    s << "<line x1=\"" << Num(X(x)) << "\" y1=\"" << Num(bottom) << "\" x2=\"" << Num(X(x)) << "\" y2=\""
      << Num(bottom + 5) << "\" stroke=\"#000000\"/><text x=\"" << Num(X(x)) << "\" y=\"" << Num(bottom + 18)
      << "\" font-size=\"11\" text-anchor=\"middle\">" << Short(x) << "</text>\n";
  for (double y = std::ceil(y0_ / step) * step; y <= y1_; y += step)
    s << "<line x1=\"" << Num(kLeft - 5) << "\" y1=\"" << Num(Y(y)) << "\" x2=\"" << Num(kLeft) << "\" y2=\""
      << Num(Y(y)) << "\" stroke=\"#000000\"/><text x=\"" << Num(kLeft - 8) << "\" y=\"" << Num(Y(y) + 4)
      << "\" font-size=\"11\" text-anchor=\"end\">" << Short(y) << "</text>\n";
  s << "<text x=\"" << Num(kLeft + kPlotWidth / 2) << "\" y=\"" << Num(height() - 8)
    << "\" font-size=\"12\" text-anchor=\"middle\">x (m)</text>\n<text x=\"14\" y=\"" << Num(kTop + 4)
    << "\" font-size=\"12\">y (m)</text>\n";
}

// A bar of a round length in the plot's bottom-left corner.
void Frame::ScaleBar(std::ostringstream& s) const {
  const double metres = NiceStep(120 / scale_, 1);
  const double y = height() - kBottom - 12, x = kLeft + 12;
  s << "<line x1=\"" << Num(x) << "\" y1=\"" << Num(y) << "\" x2=\"" << Num(x + metres * scale_) << "\" y2=\"" << Num(y)
    << "\" stroke=\"#000000\" stroke-width=\"2\"/><text x=\"" << Num(x) << "\" y=\"" << Num(y - 5)
    << "\" font-size=\"11\">" << Short(metres) << " m</text>\n";
}

bool Labels::Place(std::ostringstream& s, double x, double y, const std::string& text, double size, const char* color,
                   const char* anchor) {
  const double w = 0.6 * size * text.size(), h = size;
  const double left = std::string(anchor) == "middle" ? x - w / 2 : x;
  const Box box{left, y - h, left + w, y + 2};
  for (const Box& b : placed_)
    if (box.x0 < b.x1 && b.x0 < box.x1 && box.y0 < b.y1 && b.y0 < box.y1) return false;
  placed_.push_back(box);
  s << "<text x=\"" << Num(x) << "\" y=\"" << Num(y) << "\" font-size=\"" << Num(size) << "\" fill=\"" << color
    << "\" text-anchor=\"" << anchor << "\">" << Escape(text) << "</text>\n";
  return true;
}

void Legend::Text(std::ostringstream& s, const std::string& text) {
  s << "<text x=\"" << Num(x_ + 26) << "\" y=\"" << Num(y_ + 4) << "\" font-size=\"11\">" << Escape(text)
    << "</text>\n";
  y_ += 18;
}

void Legend::Line(std::ostringstream& s, const char* color, const std::string& text) {
  s << "<line x1=\"" << Num(x_) << "\" y1=\"" << Num(y_) << "\" x2=\"" << Num(x_ + 20) << "\" y2=\"" << Num(y_)
    << "\" stroke=\"" << color << "\" stroke-width=\"2\"/>\n";
  Text(s, text);
}

void Legend::Square(std::ostringstream& s, const char* color, const std::string& text) {
  s << "<rect x=\"" << Num(x_ + 6) << "\" y=\"" << Num(y_ - 4) << "\" width=\"8\" height=\"8\" fill=\"" << color
    << "\"/>\n";
  Text(s, text);
}

void Legend::Dot(std::ostringstream& s, const char* color, const std::string& text) {
  s << "<circle cx=\"" << Num(x_ + 10) << "\" cy=\"" << Num(y_) << "\" r=\"3\" fill=\"" << color << "\"/>\n";
  Text(s, text);
}

// From pale yellow to dark blue through green, so that shades are told apart in print too.
std::string ScaleColor(double share) {
  static const int stops[][3] = {{255, 247, 188}, {120, 198, 121}, {35, 132, 67}, {8, 64, 129}};
  share = std::clamp(share, 0.0, 1.0) * 3;
  const int i = std::min(2, static_cast<int>(share));
  const double f = share - i;
  char color[16];
  std::snprintf(color, sizeof color, "#%02x%02x%02x",
                static_cast<int>(std::lround(stops[i][0] + f * (stops[i + 1][0] - stops[i][0]))),
                static_cast<int>(std::lround(stops[i][1] + f * (stops[i + 1][1] - stops[i][1]))),
                static_cast<int>(std::lround(stops[i][2] + f * (stops[i + 1][2] - stops[i][2]))));
  return color;
}

void ColorBar(std::ostringstream& s, double x, double y, double low, double high, const std::string& unit) {
  constexpr int kSteps = 20;
  for (int i = 0; i < kSteps; ++i)
    s << "<rect x=\"" << Num(x) << "\" y=\"" << Num(y + (kSteps - 1 - i) * 8)
      << "\" width=\"16\" height=\"8.5\" fill=\"" << ScaleColor((i + 0.5) / kSteps) << "\"/>\n";
  s << "<rect x=\"" << Num(x) << "\" y=\"" << Num(y) << "\" width=\"16\" height=\"" << kSteps * 8
    << "\" fill=\"none\" stroke=\"#333333\"/>\n";
  for (double share : {0.0, 0.5, 1.0})
    s << "<text x=\"" << Num(x + 22) << "\" y=\"" << Num(y + (1 - share) * kSteps * 8 + 4) << "\" font-size=\"11\">"
      << Short(std::round(low + share * (high - low))) << "</text>\n";
  s << "<text x=\"" << Num(x) << "\" y=\"" << Num(y - 8) << "\" font-size=\"11\">" << Escape(unit) << "</text>\n";
}

}  // namespace sanet::trace::svg
