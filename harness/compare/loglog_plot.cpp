#include "harness/compare/loglog_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "harness/compare/svg_markup.hpp"
#include "harness/core/error.hpp"
#include "harness/core/text_format.hpp"

namespace vsgl {
namespace {

bool on_log_axis(double v) { return std::isfinite(v) && v > 0; }

// Whole decades [low, high] around the values, at least one.
struct Decades {
  double low = 0, high = 1;

  Decades(double min, double max) : low(std::floor(std::log10(min))), high(std::ceil(std::log10(max))) {
    if (high < low + 1) high = low + 1;
  }
  double fraction(double v) const { return (std::log10(v) - low) / (high - low); }
};

// Written out ("0.002", "50000") on an axis within 0.001 ... 100000, else all as "2e6", so the
// labels of one axis read alike.
std::string axis_label(double v, bool written_out) {
  if (written_out) return number_text(v, 6);
  const int exponent = static_cast<int>(std::floor(std::log10(v) + 1e-9));
  const double mantissa = std::round(v / std::pow(10.0, exponent));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0fe%d", mantissa, exponent);
  return buf;
}

std::string diamond(double cx, double cy, double r) {
  return "M" + svg_number(cx) + "," + svg_number(cy - r) + " L" + svg_number(cx + r) + "," + svg_number(cy) + " L" +
         svg_number(cx) + "," + svg_number(cy + r) + " L" + svg_number(cx - r) + "," + svg_number(cy) + " Z";
}

std::string line(const char* css_class, double x1, double y1, double x2, double y2, const std::string& stroke) {
  return "<line class=\"" + std::string(css_class) + "\" x1=\"" + svg_number(x1) + "\" y1=\"" + svg_number(y1) +
         "\" x2=\"" + svg_number(x2) + "\" y2=\"" + svg_number(y2) + "\" stroke=\"" + xml_escape(stroke) + "\"/>";
}

// The checked, sorted input of one series.
struct Prepared {
  const LogLogSeries* series = nullptr;
  std::string color;
  std::vector<LogLogPoint> points;
  std::vector<std::string> reference_labels;  // distinct, in first-seen order: one legend entry each
};

std::vector<Prepared> prepare(const LogLogPlot& plot, const std::vector<LogLogSeries>& series) {
  const std::string what = "log-log plot '" + plot.title + "'";
  if (plot.width < 240 || plot.plot_height < 120)
    throw InputError(what + ": a width of " + std::to_string(plot.width) + " and a plot height of " +
                     std::to_string(plot.plot_height) + " leave no room (at least 240 and 120)");
  if (series.empty()) throw InputError(what + ": no series to draw");
  std::vector<Prepared> out;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const LogLogSeries& s = series[i];
    const std::string at = what + ", series '" + s.name + "'";
    if (s.points.empty()) throw InputError(at + ": no points");
    Prepared p{&s, s.color.empty() ? series_color(i) : s.color, s.points, {}};
    for (const LogLogPoint& pt : p.points) {
      if (!on_log_axis(pt.x))
        throw InputError(at + ": x = " + number_text(pt.x) +
                         " cannot be placed on a log axis (a finite positive number)");
      if (!on_log_axis(pt.median) || !on_log_axis(pt.q1) || !on_log_axis(pt.q3) || pt.q1 > pt.median ||
          pt.q3 < pt.median)
        throw InputError(at + " at x = " + number_text(pt.x) + ": median " + number_text(pt.median) +
                         " ms, quartiles " + number_text(pt.q1) + " and " + number_text(pt.q3) +
                         " ms are not positive times with q1 <= median <= q3");
    }
    std::stable_sort(p.points.begin(), p.points.end(),
                     [](const LogLogPoint& a, const LogLogPoint& b) { return a.x < b.x; });
    for (std::size_t k = 1; k < p.points.size(); ++k)
      if (p.points[k].x == p.points[k - 1].x)
        throw InputError(at + ": two points at x = " + number_text(p.points[k].x));
    for (const LogLogReference& r : s.references) {
      if (!on_log_axis(r.x) || !on_log_axis(r.ms))
        throw InputError(at + ": reference '" + r.label + "' at x = " + number_text(r.x) + ", " + number_text(r.ms) +
                         " ms cannot be placed on log axes (finite positive numbers)");
      if (std::find(p.reference_labels.begin(), p.reference_labels.end(), r.label) == p.reference_labels.end())
        p.reference_labels.push_back(r.label);
    }
    out.push_back(std::move(p));
  }
  return out;
}

// Where everything goes: the decades of both axes (covering every quartile and reference), the
// plotting area, and the legend below it, one row per series and per reference label.
struct Layout {
  Decades x, y;
  double left = 72, right = 20, top = 34, row = 16;
  double plot_w = 0, plot_h = 0, legend_top = 0;
  int width = 0, height = 0;

  double x_of(double v) const { return left + plot_w * x.fraction(v); }
  double y_of(double v) const { return top + plot_h * (1.0 - y.fraction(v)); }
};

Layout layout(const LogLogPlot& plot, const std::vector<Prepared>& prepared) {
  double x_min = INFINITY, x_max = 0, y_min = INFINITY, y_max = 0;
  std::size_t legend_rows = 0;
  for (const Prepared& p : prepared) {
    for (const LogLogPoint& pt : p.points) {
      x_min = std::min(x_min, pt.x), x_max = std::max(x_max, pt.x);
      y_min = std::min(y_min, pt.q1), y_max = std::max(y_max, pt.q3);
    }
    for (const LogLogReference& r : p.series->references) {
      x_min = std::min(x_min, r.x), x_max = std::max(x_max, r.x);
      y_min = std::min(y_min, r.ms), y_max = std::max(y_max, r.ms);
    }
    legend_rows += 1 + p.reference_labels.size();
  }
  Layout l{Decades(x_min, x_max), Decades(y_min, y_max)};
  l.plot_w = plot.width - l.left - l.right;
  l.plot_h = plot.plot_height;
  l.legend_top = l.top + l.plot_h + 58;
  l.width = plot.width;
  l.height = static_cast<int>(std::ceil(l.legend_top + l.row * static_cast<double>(legend_rows) + 4));
  return l;
}

// Grid and ticks of one axis: a line at every 1..9 x 10^k; labels at the decades (thinned to
// about eight), and at 2 and 5 as well when the axis spans at most two decades.
void draw_ticks(std::ostringstream& os, const Layout& l, bool horizontal) {
  const Decades& d = horizontal ? l.y : l.x;
  const double span = d.high - d.low;
  const int label_every = std::max(1, static_cast<int>(std::ceil(span / 8)));
  const bool written_out = d.low >= -3 && d.high <= 5;
  for (double k = d.low; k <= d.high + 1e-9; k += 1) {
    for (int m = 1; m <= 9; ++m) {
      if (k == d.high && m > 1) break;
      const double v = m * std::pow(10.0, k);
      const bool decade = m == 1;
      const bool labelled = decade ? static_cast<int>(k - d.low) % label_every == 0 : span <= 2 && (m == 2 || m == 5);
      const std::string stroke = decade ? "#c8c8c8" : "#ececec";
      const char* cls = decade ? "grid decade" : "grid";
      if (horizontal) {
        os << line(cls, l.left, l.y_of(v), l.left + l.plot_w, l.y_of(v), stroke);
        if (labelled) os << svg_text(l.left - 5, l.y_of(v) + 4, axis_label(v, written_out), "tick y-tick", "end");
      } else {
        os << line(cls, l.x_of(v), l.top, l.x_of(v), l.top + l.plot_h, stroke);
        if (labelled) os << svg_text(l.x_of(v), l.top + l.plot_h + 16, axis_label(v, written_out), "tick x-tick");
      }
    }
  }
}

// The title, both axes' grids and ticks, the frame and the axis titles.
void draw_axes(std::ostringstream& os, const LogLogPlot& plot, const Layout& l) {
  os << "<title>" << xml_escape(plot.title) << "</title>";
  os << "<rect class=\"background\" x=\"0\" y=\"0\" width=\"" << l.width << "\" height=\"" << l.height
     << "\" fill=\"#ffffff\"/>";
  os << svg_text(l.width / 2.0, 20, plot.title, "title");
  draw_ticks(os, l, false);
  draw_ticks(os, l, true);
  os << "<rect class=\"frame\" x=\"" << svg_number(l.left) << "\" y=\"" << svg_number(l.top) << "\" width=\""
     << svg_number(l.plot_w) << "\" height=\"" << svg_number(l.plot_h) << "\" fill=\"none\" stroke=\"#333333\"/>";
  os << svg_text(l.left + l.plot_w / 2, l.top + l.plot_h + 36, plot.x_title, "axis-title x-title");
  const double y_title_x = 18, y_title_y = l.top + l.plot_h / 2;
  os << "<text x=\"" << svg_number(y_title_x) << "\" y=\"" << svg_number(y_title_y)
     << "\" class=\"axis-title y-title\" text-anchor=\"middle\" transform=\"rotate(-90 " << svg_number(y_title_x) << " "
     << svg_number(y_title_y) << ")\">" << xml_escape(plot.y_title) << "</text>";
}

// One series: its q1..q3 band and median line (a whisker for a single point), a marker per point
// and a diamond per reference, each with its tooltip.
void draw_series(std::ostringstream& os, const Layout& l, const Prepared& p) {
  const LogLogSeries& s = *p.series;
  const std::string color = xml_escape(p.color);
  os << "<g class=\"series\" data-series=\"" << xml_escape(s.name) << "\">";
  if (p.points.size() > 1) {
    os << "<path class=\"band\" d=\"";
    for (std::size_t k = 0; k < p.points.size(); ++k)
      os << (k == 0 ? "M" : " L") << svg_number(l.x_of(p.points[k].x)) << "," << svg_number(l.y_of(p.points[k].q3));
    for (std::size_t k = p.points.size(); k-- > 0;)
      os << " L" << svg_number(l.x_of(p.points[k].x)) << "," << svg_number(l.y_of(p.points[k].q1));
    os << " Z\" fill=\"" << color << "\" fill-opacity=\"0.18\" stroke=\"none\"/>";
    os << "<path class=\"line\" d=\"";
    for (std::size_t k = 0; k < p.points.size(); ++k)
      os << (k == 0 ? "M" : " L") << svg_number(l.x_of(p.points[k].x)) << "," << svg_number(l.y_of(p.points[k].median));
    os << "\" fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.8\"/>";
  } else {
    const LogLogPoint& pt = p.points.front();
    os << line("whisker", l.x_of(pt.x), l.y_of(pt.q1), l.x_of(pt.x), l.y_of(pt.q3), p.color);
  }
  for (const LogLogPoint& pt : p.points) {
    const std::string tip = !pt.tooltip.empty()
                                ? pt.tooltip
                                : s.name + ": x = " + number_text(pt.x, 6) + ", median " + number_text(pt.median, 4) +
                                      " ms (q1 " + number_text(pt.q1, 4) + ", q3 " + number_text(pt.q3, 4) + ")";
    os << "<circle class=\"point\" cx=\"" << svg_number(l.x_of(pt.x)) << "\" cy=\"" << svg_number(l.y_of(pt.median))
       << "\" r=\"3.5\" fill=\"" << color << "\"><title>" << xml_escape(tip) << "</title></circle>";
  }
  for (const LogLogReference& r : s.references) {
    const std::string tip = !r.tooltip.empty() ? r.tooltip
                                               : s.name + " (" + r.label + "): x = " + number_text(r.x, 6) + ", " +
                                                     number_text(r.ms, 4) + " ms";
    os << "<path class=\"reference\" data-label=\"" << xml_escape(r.label) << "\" d=\""
       << diamond(l.x_of(r.x), l.y_of(r.ms), 6) << "\" fill=\"#ffffff\" stroke=\"" << color
       << "\" stroke-width=\"2\"><title>" << xml_escape(tip) << "</title></path>";
  }
  os << "</g>";
}

// Legend below the axis title, one entry a row: a series as its line and marker, a reference
// label as its diamond.
void draw_legend(std::ostringstream& os, const Layout& l, const std::vector<Prepared>& prepared) {
  os << "<g class=\"legend\">";
  double ly = l.legend_top;
  for (const Prepared& p : prepared) {
    const std::string color = xml_escape(p.color);
    os << line("legend-line", l.left, ly - 4, l.left + 20, ly - 4, p.color);
    os << "<circle class=\"legend-point\" cx=\"" << svg_number(l.left + 10) << "\" cy=\"" << svg_number(ly - 4)
       << "\" r=\"3.5\" fill=\"" << color << "\"/>";
    os << svg_text(l.left + 28, ly, p.series->name, "legend-label", "start");
    ly += l.row;
    for (const std::string& label : p.reference_labels) {
      os << "<path class=\"legend-reference\" d=\"" << diamond(l.left + 10, ly - 4, 5)
         << "\" fill=\"#ffffff\" stroke=\"" << color << "\" stroke-width=\"2\"/>";
      os << svg_text(l.left + 28, ly, p.series->name + ": " + label, "legend-label", "start");
      ly += l.row;
    }
  }
  os << "</g>";
}

}  // namespace

std::string loglog_plot_svg(const LogLogPlot& plot, const std::vector<LogLogSeries>& series) {
  const std::vector<Prepared> prepared = prepare(plot, series);
  const Layout l = layout(plot, prepared);
  std::ostringstream os;
  os << svg_open("loglog", plot.width, l.height, plot.title);
  draw_axes(os, plot, l);
  for (const Prepared& p : prepared) draw_series(os, l, p);
  draw_legend(os, l, prepared);
  os << "</svg>";
  return os.str();
}

}  // namespace vsgl
