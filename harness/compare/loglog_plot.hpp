#pragma once
// A standalone SVG log-log chart of cost over a parameter (DESIGN.md §9.1): per series a line
// through the medians over a shaded band from q1 to q3, a marker per point, and optional
// reference values (the paper's) drawn as hollow diamonds with their own legend entry. Axes in
// whole decades with labelled ticks. The same input gives the same bytes; all text is escaped.
// Elements carry the classes the tests look for ("series", "line", "band", "point", "whisker",
// "reference", "legend").
#include <string>
#include <vector>

namespace vsgl {

struct LogLogPoint {
  double x = 0;           // the parameter, finite and > 0
  double median = 0;      // ms, > 0
  double q1 = 0, q3 = 0;  // ms, 0 < q1 <= median <= q3
  std::string tooltip;    // empty: the series, x, median and quartiles
};

// A value to compare against, e.g. the paper's time at the paper's parameter.
struct LogLogReference {
  double x = 0;                 // finite and > 0
  double ms = 0;                // finite and > 0
  std::string label = "paper";  // the legend says "<series>: <label>"
  std::string tooltip;          // empty: the series, label, x and ms
};

struct LogLogSeries {
  std::string name;                 // e.g. the generator
  std::string color;                // CSS colour; empty: series_color(index of the series)
  std::vector<LogLogPoint> points;  // any order, drawn sorted by x; each x once
  std::vector<LogLogReference> references;
};

struct LogLogPlot {
  std::string title;
  std::string x_title;  // e.g. "N (lights)"
  std::string y_title = "ms";
  int width = 640;        // >= 240
  int plot_height = 320;  // the plotting area, >= 120; titles, ticks and legend add to it
};

// The chart as one <svg> element. A one-point series has no line or band: its marker gets a
// whisker from q1 to q3 instead. Throws InputError (nothing drawn) for no series, a series
// without points or with two points at one x, a value that cannot sit on a log axis (zero,
// negative, not finite), quartiles that do not enclose the median, or a size below the minimum.
std::string loglog_plot_svg(const LogLogPlot& plot, const std::vector<LogLogSeries>& series);

}  // namespace vsgl
