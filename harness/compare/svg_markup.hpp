#pragma once
// The pieces every chart of this folder is written with (dashboard_svg, loglog_plot): escaped
// text, coordinates with one decimal (a chart's bytes depend on nothing but its data), the
// series palette and the way times are labelled.
#include <cstddef>
#include <string>

namespace vsgl {

// Text safe inside XML character data and attribute values.
std::string xml_escape(const std::string& text);

// A coordinate or length, one decimal ("12.5").
std::string svg_number(double v);

// <text> at (x, y) with class `css_class` and text-anchor `anchor`; `s` is escaped.
std::string svg_text(double x, double y, const std::string& s, const std::string& css_class,
                     const std::string& anchor = "middle");

// The opening <svg> tag: class "chart <css_class>", the size, and `title` as its aria-label.
std::string svg_open(const std::string& css_class, int width, int height, const std::string& title);

// A time in ms as a label: whole ms from 100, then one, two, or three significant decimals.
std::string ms_label(double ms);

// The i-th series colour (CSS), cycling through eight that stay apart on white.
const char* series_color(std::size_t i);

}  // namespace vsgl
