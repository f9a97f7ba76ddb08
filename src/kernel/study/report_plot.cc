// Plot of a report with PLplot: the mean of each value with its 95 % interval as error bars, a
// line per series, a legend when there are several.
#include <plplot/plplot.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "study/grid.h"
#include "study/report.h"

namespace sanet::study {
namespace {

constexpr int kBlack = 1, kFirstSeries = 2;
// The page's share of height per legend line, and how far under the plot (in its heights) the
// legend starts, clear of the x axis's label.
constexpr double kLegendLine = 0.05, kLegendDrop = 0.24;
// Series colours: the same palette as the run figures.
constexpr int kPalette[][3] = {{31, 119, 180},  {214, 39, 40},  {44, 160, 44},
                               {148, 103, 189}, {255, 127, 14}, {140, 86, 75}};

bool NumericAxis(const std::vector<Series>& series) {
  for (const Series& s : series)
    for (const Point& p : s.points)
      if (!NumberIn(p.x)) return false;
  return true;
}

// The x of every value: itself on a numeric axis, else its place among all values (1, 2, ...).
std::vector<std::string> Categories(const std::vector<Series>& series) {
  std::vector<std::string> all;
  for (const Series& s : series)
    for (const Point& p : s.points)
      if (std::find(all.begin(), all.end(), p.x) == all.end()) all.push_back(p.x);
  return all;
}

struct Frame {
  double x0, x1, y0, y1;
};

Frame Bounds(const std::vector<Series>& series, bool numeric, std::size_t categories) {
  Frame f{1e300, -1e300, 1e300, -1e300};
  for (const Series& s : series)
    for (const Point& p : s.points) {
      f.y0 = std::min(f.y0, p.stats.mean - p.stats.half_width);
      f.y1 = std::max(f.y1, p.stats.mean + p.stats.half_width);
      if (numeric) f.x0 = std::min(f.x0, std::stod(p.x)), f.x1 = std::max(f.x1, std::stod(p.x));
    }
  if (!numeric) f.x0 = 1, f.x1 = static_cast<double>(categories);
  const double xpad = f.x1 > f.x0 ? 0.06 * (f.x1 - f.x0) : 0.5, ypad = f.y1 > f.y0 ? 0.08 * (f.y1 - f.y0) : 0.5;
  return {f.x0 - xpad, f.x1 + xpad, f.y0 - ypad, f.y1 + ypad};
}

void Colours(std::size_t series) {
  plscol0(0, 255, 255, 255);  // background
  plscol0(kBlack, 0, 0, 0);   // axes and text
  for (std::size_t i = 0; i < series && i < 6; ++i)
    plscol0(kFirstSeries + static_cast<int>(i), kPalette[i][0], kPalette[i][1], kPalette[i][2]);
}

void DrawSeries(const Series& s, int colour, bool numeric, const std::vector<std::string>& categories) {
  std::vector<double> x, y, lo, hi;
  for (const Point& p : s.points) {
    x.push_back(
        numeric ? std::stod(p.x)
                : 1.0 + static_cast<double>(std::find(categories.begin(), categories.end(), p.x) - categories.begin()));
    y.push_back(p.stats.mean);
    lo.push_back(p.stats.mean - p.stats.half_width);
    hi.push_back(p.stats.mean + p.stats.half_width);
  }
  const int n = static_cast<int>(x.size());
  plcol0(colour);
  plwidth(2);
  plline(n, x.data(), y.data());
  plerry(n, x.data(), lo.data(), hi.data());
  plpoin(n, x.data(), y.data(), 17);
}

void Legend(const std::vector<Series>& series) {
  const int n = static_cast<int>(series.size());
  std::vector<PLINT> opts(n, PL_LEGEND_LINE), colours(n), styles(n, 1), text_colours(n, kBlack);
  std::vector<PLFLT> widths(n, 2.0);
  std::vector<const char*> texts(n);
  for (int i = 0; i < n; ++i)
    colours[i] = kFirstSeries + i % 6, styles[i] = 1 + i / 6 % 8, texts[i] = series[i].label.c_str();
  PLFLT width = 0, height = 0;
  pllegend(&width, &height, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, PL_POSITION_BOTTOM | PL_POSITION_OUTSIDE,
           0.0, kLegendDrop, 0.08, 0, kBlack, 1, 0, 0, n, opts.data(), 1.0, 0.8, 2.0, 0.0, text_colours.data(),
           texts.data(), nullptr, nullptr, nullptr, nullptr, colours.data(), styles.data(), widths.data(), nullptr,
           nullptr, nullptr, nullptr);
}

}  // namespace

void CheckPlotName(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext != ".svg" && ext != ".png") throw ReportError("--plot: give a file ending in .svg or .png, not " + path);
}

namespace {

// Every line of the plot: each metric's series, labelled by the metric where there are several.
std::vector<Series> Lines(const std::vector<MetricSeries>& metrics) {
  std::vector<Series> lines;
  for (const MetricSeries& m : metrics)
    for (const Series& s : m.series) {
      std::string label = metrics.size() == 1 ? s.label : m.metric + (s.label.empty() ? "" : " (" + s.label + ")");
      lines.push_back({label, s.points});
    }
  return lines;
}

PlotText Defaults(PlotText text, const std::vector<MetricSeries>& metrics, const std::string& by) {
  if (text.xlabel.empty()) text.xlabel = by.empty() ? "all runs" : ShortName(by);
  if (text.ylabel.empty()) text.ylabel = metrics.size() == 1 ? metrics.front().metric : "value";
  if (text.title.empty())
    text.title = "mean and 95% confidence interval" + std::string(by.empty() ? "" : " against " + ShortName(by));
  return text;
}

}  // namespace

void Plot(const std::vector<MetricSeries>& metrics, const std::string& by, const PlotText& asked,
          const std::string& path) {
  CheckPlotName(path);
  const std::string ext = std::filesystem::path(path).extension().string();
  const std::vector<Series> series = Lines(metrics);
  const bool numeric = NumericAxis(series);
  const std::vector<std::string> categories = Categories(series);
  if (categories.empty()) throw ReportError("nothing to plot: no completed run has a value");
  const Frame f = Bounds(series, numeric, categories.size());
  const PlotText text = Defaults(asked, metrics, by);
  const std::string tmp = path + ".tmp" + ext;
  plsdev(ext == ".svg" ? "svg" : "pngcairo");
  plsfnam(tmp.c_str());
  plspage(0, 0, 900, 600, 0, 0);
  Colours(series.size());
  plinit();
  plcol0(kBlack);
  // A legend goes under the plot, a line each, so that it never covers a point.
  pladv(0);
  plvpor(0.1, 0.95,
         series.size() > 1 ? 0.18 + kLegendLine * static_cast<double>(std::min<std::size_t>(series.size(), 8)) : 0.12,
         0.9);
  plwind(f.x0, f.x1, f.y0, f.y1);
  plbox(numeric ? "bcnst" : "bc", 0, 0, "bcnstv", 0, 0);
  if (!numeric) {
    for (std::size_t i = 0; i < categories.size(); ++i)
      plmtex("b", 1.5, (1.0 + i - f.x0) / (f.x1 - f.x0), 0.5, categories[i].c_str());
  }
  pllab(text.xlabel.c_str(), text.ylabel.c_str(), text.title.c_str());
  for (std::size_t i = 0; i < series.size(); ++i) {
    pllsty(1 + static_cast<int>(i / 6 % 8));  // past six colours, the line style tells them apart
    DrawSeries(series[i], kFirstSeries + static_cast<int>(i % 6), numeric, categories);
  }
  pllsty(1);
  if (series.size() > 1) Legend(series);
  plend();
  std::filesystem::rename(tmp, path);
}

}  // namespace sanet::study
