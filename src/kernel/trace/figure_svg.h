// What the figures share: numbers and text for SVG, a frame from world metres to pixels with
// axes, and labels that do not overlap. Every figure is a plain SVG that browsers, rsvg-convert
// and ImageMagick draw alike: a white background under everything, no elements nested in shapes.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "trace/figures.h"

namespace sanet::trace::svg {

// Colours of the robots' tracks, in node order (repeated after six).
constexpr const char* kColors[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

std::string Num(double v);    // 1 decimal
std::string Short(double v);  // as few decimals as it needs (tick labels)
std::string Escape(const std::string& text);
// A round step for about `count` ticks over `span`: 1, 2 or 5 times a power of ten.
double NiceStep(double span, int count);

// Axis-aligned picture of a world area, equal scale on both axes, in a plot area with room for
// the title, axes and a legend on the right.
class Frame {
 public:
  static constexpr double kLeft = 64, kTop = 44, kBottom = 48, kRight = 170, kPlotWidth = 640;
  Frame(double x0, double x1, double y0, double y1);
  static Frame Around(const FigureInput& in);
  double X(double x) const { return kLeft + (x - x0_) * scale_; }
  double Y(double y) const { return kTop + (y1_ - y) * scale_; }
  double width() const { return kLeft + kPlotWidth + kRight; }
  double height() const { return kTop + (y1_ - y0_) * scale_ + kBottom; }
  double scale() const { return scale_; }  // px per metre
  std::string Point(double x, double y) const { return Num(X(x)) + "," + Num(Y(y)); }
  // The opening of the document (white background, title) and the axes with their units.
  void Open(std::ostringstream& s, const std::string& title) const;
  void Axes(std::ostringstream& s) const;
  void ScaleBar(std::ostringstream& s) const;

 private:
  double x0_, x1_, y0_, y1_, scale_;
};

// Places text where it overlaps nothing placed before; false (and nothing placed) otherwise.
class Labels {
 public:
  bool Place(std::ostringstream& s, double x, double y, const std::string& text, double size, const char* color,
             const char* anchor = "start");

 private:
  struct Box {
    double x0, y0, x1, y1;
  };
  std::vector<Box> placed_;
};

// A legend in the right margin, one row per entry.
class Legend {
 public:
  Legend(const Frame& f) : x_(f.width() - Frame::kRight + 14), y_(Frame::kTop + 6) {}
  void Line(std::ostringstream& s, const char* color, const std::string& text);
  void Square(std::ostringstream& s, const char* color, const std::string& text);
  void Dot(std::ostringstream& s, const char* color, const std::string& text);
  double next_y() const { return y_; }

 private:
  void Text(std::ostringstream& s, const std::string& text);
  double x_, y_;
};

// Colours of a sequential scale from light (share 0) to dark (share 1), and the bar that shows it.
std::string ScaleColor(double share);
void ColorBar(std::ostringstream& s, double x, double y, double low, double high, const std::string& unit);

}  // namespace sanet::trace::svg
