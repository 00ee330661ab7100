#pragma once
// The charts of `vsgl-bench dashboard` (DESIGN.md §10) as inline SVG text: no script, no library, no
// network — the page shows them as written. Every drawn value carries a <title> (the browser's
// tooltip) with its number, and the elements carry classes the tests look for
// ("chart", "bar", "segment", "point", ...).
#include <string>
#include <vector>

namespace vsgl {

struct BarSegment {
  std::string key;      // legend key (a phase)
  double value = 0;     // ms, >= 0
  std::string tooltip;
};

struct StackedBar {
  std::string label;    // under the bar
  std::vector<BarSegment> segments;  // bottom to top
};

struct LegendEntry {
  std::string key;
  std::string label;
  std::string color;    // CSS colour
};

// One bar per entry of `bars`, segments stacked, linear axis from 0 with ticks, the total above
// each bar. `css_class` is added to the <svg> (e.g. "paper" or "run"). Throws
// std::invalid_argument for a negative or non-finite value or a segment key without a legend
// entry.
std::string stacked_bar_chart_svg(const std::string& title, const std::string& css_class,
                                  const std::vector<StackedBar>& bars, const std::vector<LegendEntry>& legend,
                                  int width, int height);

struct SeriesPoint {
  std::size_t x = 0;    // index into the x labels
  double value = 0;     // > 0
  double low = 0;       // whisker (q1), 0 < low <= value
  double high = 0;      // whisker (q3), >= value
  std::string tooltip;
};

struct Series {
  std::string name;
  std::string color;
  std::vector<SeriesPoint> points;  // in x order
};

// Points joined per series over x positions (runs in time order), whiskers low..high, on a log
// axis (devices differ by orders of magnitude). Throws std::invalid_argument for a non-positive
// value or an x outside the labels.
std::string time_series_svg(const std::string& title, const std::vector<std::string>& x_labels,
                            const std::vector<Series>& series, int width, int height);

}  // namespace vsgl
