#include "harness/compare/dashboard_svg.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "harness/compare/svg_markup.hpp"

namespace vsgl {
namespace {

// A "nice" step (1, 2 or 5 times a power of ten) giving about `ticks` intervals up to `max`.
double nice_step(double max, int ticks) {
  const double raw = max / ticks;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * mag) return m * mag;
  return 10.0 * mag;
}

}  // namespace

std::string stacked_bar_chart_svg(const std::string& title, const std::string& css_class, const std::vector<StackedBar>& bars,
                                  const std::vector<LegendEntry>& legend, int width, int height) {
  std::map<std::string, const LegendEntry*> colors;
  for (const auto& e : legend) colors[e.key] = &e;
  double max_total = 0;
  for (const auto& b : bars) {
    double total = 0;
    for (const auto& s : b.segments) {
      if (!std::isfinite(s.value) || s.value < 0) throw std::invalid_argument(title + ": a bar segment is not a time");
      if (!colors.contains(s.key)) throw std::invalid_argument(title + ": segment '" + s.key + "' has no legend entry");
      total += s.value;
    }
    max_total = std::max(max_total, total);
  }
  if (!(max_total > 0)) max_total = 1;
  const double w = static_cast<double>(width), h = static_cast<double>(height);
  const double left = 52, right = 8, top = 28;
  const auto legend_item_width = [](const LegendEntry& e) { return 16 + 6.2 * static_cast<double>(e.label.size()) + 10; };
  double legend_rows = legend.empty() ? 0 : 1;
  for (double lx = left; const auto& e : legend) {
    if (lx + legend_item_width(e) > w - right && lx > left) {
      lx = left;
      legend_rows += 1;
    }
    lx += legend_item_width(e);
  }
  const double bottom = 30 + 14 * legend_rows;
  const double plot_w = w - left - right, plot_h = h - top - bottom;
  const double step = nice_step(max_total, 4);
  const double axis_max = std::ceil(max_total / step - 1e-9) * step;
  const auto y_of = [&](double v) { return top + plot_h * (1.0 - v / axis_max); };

  std::ostringstream os;
  os << svg_open("bars " + css_class, width, height, title);
  os << "<title>" << xml_escape(title) << "</title>";
  os << "<rect class=\"background\" x=\"0\" y=\"0\" width=\"" << width << "\" height=\"" << height << "\" fill=\"#ffffff\"/>";
  os << svg_text(w / 2, 16, title, "title");
  for (double t = 0; t <= axis_max + step * 1e-6; t += step) {
    os << "<line class=\"grid\" x1=\"" << svg_number(left) << "\" x2=\"" << svg_number(w - right) << "\" y1=\""
       << svg_number(y_of(t)) << "\" y2=\"" << svg_number(y_of(t)) << "\" stroke=\"#dddddd\"/>";
    os << svg_text(left - 4, y_of(t) + 4, ms_label(t), "tick", "end");
  }
  os << svg_text(12, top + plot_h / 2, "ms", "axis-label");
  const double slot = plot_w / static_cast<double>(std::max<std::size_t>(bars.size(), 1));
  const double bar_w = std::min(slot * 0.6, 48.0);
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const StackedBar& b = bars[i];
    const double x = left + slot * (static_cast<double>(i) + 0.5) - bar_w / 2;
    double base = 0;
    os << "<g class=\"bar\" data-label=\"" << xml_escape(b.label) << "\">";
    for (const auto& s : b.segments) {
      const double y0 = y_of(base), y1 = y_of(base + s.value);
      os << "<rect class=\"segment\" data-phase=\"" << xml_escape(s.key) << "\" x=\"" << svg_number(x) << "\" y=\""
         << svg_number(y1) << "\" width=\"" << svg_number(bar_w) << "\" height=\"" << svg_number(std::max(y0 - y1, 0.0))
         << "\" fill=\"" << colors[s.key]->color << "\"><title>" << xml_escape(s.tooltip) << "</title></rect>";
      base += s.value;
    }
    os << svg_text(x + bar_w / 2, y_of(base) - 3, ms_label(base), "bar-total");
    os << svg_text(x + bar_w / 2, top + plot_h + 14, b.label, "bar-label");
    os << "</g>";
  }
  os << "<line class=\"axis\" x1=\"" << svg_number(left) << "\" x2=\"" << svg_number(w - right) << "\" y1=\""
     << svg_number(top + plot_h) << "\" y2=\"" << svg_number(top + plot_h) << "\" stroke=\"#333333\"/>";
  // Legend below the labels, wrapping.
  double lx = left, ly = top + plot_h + 32;
  for (const auto& e : legend) {
    const double item_w = legend_item_width(e);
    if (lx + item_w > w - right && lx > left) {
      lx = left;
      ly += 14;
    }
    os << "<rect class=\"legend-swatch\" x=\"" << svg_number(lx) << "\" y=\"" << svg_number(ly - 9)
       << "\" width=\"10\" height=\"10\" fill=\"" << e.color << "\"/>";
    os << svg_text(lx + 14, ly, e.label, "legend", "start");
    lx += item_w;
  }
  os << "</svg>";
  return os.str();
}

std::string time_series_svg(const std::string& title, const std::vector<std::string>& x_labels, const std::vector<Series>& series,
                            int width, int height) {
  double lo = INFINITY, hi = 0;
  for (const auto& s : series)
    for (const auto& p : s.points) {
      if (!(p.value > 0) || !(p.low > 0) || !std::isfinite(p.high) || p.low > p.value || p.high < p.value)
        throw std::invalid_argument(title + ": a point is not a positive time inside its whisker");
      if (p.x >= x_labels.size()) throw std::invalid_argument(title + ": a point outside the x labels");
      lo = std::min(lo, p.low);
      hi = std::max(hi, p.high);
    }
  if (!(hi > 0)) lo = 0.1, hi = 1;
  // Decades around the data, at least one.
  const double d0 = std::floor(std::log10(lo)), d1 = std::max(std::ceil(std::log10(hi)), d0 + 1);
  const double w = static_cast<double>(width), h = static_cast<double>(height);
  const double left = 52, right = 12, top = 28, bottom = 30 + 14 * static_cast<double>(series.size());
  const double plot_w = w - left - right, plot_h = h - top - bottom;
  const auto y_of = [&](double v) { return top + plot_h * (1.0 - (std::log10(v) - d0) / (d1 - d0)); };
  const double slot = plot_w / static_cast<double>(std::max<std::size_t>(x_labels.size(), 1));
  const auto x_of = [&](std::size_t i) { return left + slot * (static_cast<double>(i) + 0.5); };

  std::ostringstream os;
  os << svg_open("timeseries", width, height, title);
  os << "<title>" << xml_escape(title) << "</title>";
  os << "<rect class=\"background\" x=\"0\" y=\"0\" width=\"" << width << "\" height=\"" << height << "\" fill=\"#ffffff\"/>";
  os << svg_text(w / 2, 16, title, "title");
  for (double d = d0; d <= d1 + 1e-9; d += 1) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, d);
      if (std::log10(v) > d1 + 1e-9) break;
      os << "<line class=\"grid\" x1=\"" << svg_number(left) << "\" x2=\"" << svg_number(w - right) << "\" y1=\""
         << svg_number(y_of(v)) << "\" y2=\"" << svg_number(y_of(v)) << "\" stroke=\""
         << (m == 1.0 ? "#cccccc" : "#eeeeee") << "\"/>";
      if (m == 1.0) os << svg_text(left - 4, y_of(v) + 4, ms_label(v), "tick", "end");
    }
  }
  os << svg_text(12, top + plot_h / 2, "ms", "axis-label");
  for (std::size_t i = 0; i < x_labels.size(); ++i) os << svg_text(x_of(i), top + plot_h + 14, x_labels[i], "x-label");
  double ly = top + plot_h + 34;
  for (const auto& s : series) {
    os << "<g class=\"series\" data-series=\"" << xml_escape(s.name) << "\">";
    if (s.points.size() > 1) {
      os << "<polyline class=\"line\" fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"1.5\" points=\"";
      for (const auto& p : s.points) os << svg_number(x_of(p.x)) << "," << svg_number(y_of(p.value)) << " ";
      os << "\"/>";
    }
    for (const auto& p : s.points) {
      os << "<line class=\"whisker\" x1=\"" << svg_number(x_of(p.x)) << "\" x2=\"" << svg_number(x_of(p.x))
         << "\" y1=\"" << svg_number(y_of(p.low)) << "\" y2=\"" << svg_number(y_of(p.high)) << "\" stroke=\"" << s.color
         << "\"/>";
      os << "<circle class=\"point\" cx=\"" << svg_number(x_of(p.x)) << "\" cy=\"" << svg_number(y_of(p.value))
         << "\" r=\"3.5\" fill=\"" << s.color << "\"><title>" << xml_escape(p.tooltip) << "</title></circle>";
    }
    os << "<rect class=\"legend-swatch\" x=\"" << svg_number(left) << "\" y=\"" << svg_number(ly - 9)
       << "\" width=\"10\" height=\"10\" fill=\"" << s.color << "\"/>"
       << svg_text(left + 14, ly, s.name, "legend", "start");
    ly += 14;
    os << "</g>";
  }
  os << "</svg>";
  return os.str();
}

}  // namespace vsgl
