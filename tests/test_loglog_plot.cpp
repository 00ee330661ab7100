// harness/compare/loglog_plot.hpp: the chart is well-formed XML with one line and one band per
// series, escaped text, reference markers in the plot and the legend, the same bytes for the same
// input, and refusals of what a log axis cannot show.
#include <gtest/gtest.h>

#include <cmath>
#include <cctype>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include "harness/compare/loglog_plot.hpp"
#include "input_error.hpp"

namespace vsgl {
namespace {

using test::input_error;

// A strict-enough reader of the generated subset of XML: every tag closed in order, attributes
// quoted, no raw '<' in values or text, '&' only as one of the five entities. Returns "" or what
// is wrong; `root` gets the first element's name.
std::string xml_problem(const std::string& s, std::string* root = nullptr) {
  std::vector<std::string> open;
  std::size_t i = 0, elements = 0;
  const auto entity_ok = [&](std::size_t at) {
    for (const char* e : {"&amp;", "&lt;", "&gt;", "&quot;", "&#39;"})
      if (s.compare(at, std::char_traits<char>::length(e), e) == 0) return true;
    return false;
  };
  const auto is_name = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':';
  };
  while (i < s.size()) {
    if (s[i] == '&' && !entity_ok(i)) return "bare & at " + std::to_string(i);
    if (s[i] == '>') return "bare > in text at " + std::to_string(i);
    if (s[i] != '<') {
      if (open.empty() && !std::isspace(static_cast<unsigned char>(s[i]))) return "text outside the root";
      ++i;
      continue;
    }
    ++i;
    const bool closing = i < s.size() && s[i] == '/';
    if (closing) ++i;
    std::string name;
    while (i < s.size() && is_name(s[i])) name += s[i++];
    if (name.empty()) return "tag without a name at " + std::to_string(i);
    if (closing) {
      if (i >= s.size() || s[i] != '>') return "malformed closing tag " + name;
      if (open.empty() || open.back() != name) return "closing " + name + " does not match";
      open.pop_back();
      ++i;
      continue;
    }
    if (open.empty() && elements > 0) return "a second root element " + name;
    if (elements++ == 0 && root != nullptr) *root = name;
    for (;;) {
      while (i < s.size() && s[i] == ' ') ++i;
      if (i >= s.size()) return "unterminated tag " + name;
      if (s[i] == '>') {
        open.push_back(name);
        ++i;
        break;
      }
      if (s.compare(i, 2, "/>") == 0) {
        i += 2;
        break;
      }
      std::string attr;
      while (i < s.size() && is_name(s[i])) attr += s[i++];
      if (attr.empty() || s.compare(i, 2, "=\"") != 0) return "malformed attribute in " + name;
      i += 2;
      while (i < s.size() && s[i] != '"') {
        if (s[i] == '<') return "raw < in attribute " + attr;
        if (s[i] == '&' && !entity_ok(i)) return "bare & in attribute " + attr;
        ++i;
      }
      if (i >= s.size()) return "unterminated attribute " + attr;
      ++i;
    }
  }
  if (!open.empty()) return "unclosed " + open.back();
  return elements == 0 ? "no element" : "";
}

std::size_t occurrences_of(const std::string& haystack, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = haystack.find(needle); at != std::string::npos; at = haystack.find(needle, at + 1)) ++n;
  return n;
}

LogLogPoint pt(double x, double median) { return {x, median, median * 0.9, median * 1.2, ""}; }

LogLogPlot plot() { return {"Filtered sampling over N", "N (lights)", "ms", 640, 320}; }

std::vector<LogLogSeries> two_series() {
  return {{"fis_tok15", "", {pt(1e3, 0.02), pt(1e4, 0.2), pt(1e5, 2.1)}, {{1e5, 1.7, "paper", ""}}},
          {"fis_modified", "#123456", {pt(1e5, 2.3), pt(1e3, 0.021), pt(3e4, 0.7), pt(1e4, 0.22)}, {}}};
}

TEST(LogLogPlot, WellFormedWithALineAndABandPerSeries) {
  const std::string svg = loglog_plot_svg(plot(), two_series());
  std::string root;
  EXPECT_EQ(xml_problem(svg, &root), "");
  EXPECT_EQ(root, "svg");
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"chart loglog\"", 0), 0u);
  EXPECT_EQ(occurrences_of(svg, "<g class=\"series\""), 2u);
  EXPECT_EQ(occurrences_of(svg, "<path class=\"line\""), 2u);
  EXPECT_EQ(occurrences_of(svg, "<path class=\"band\""), 2u);
  EXPECT_EQ(occurrences_of(svg, "<circle class=\"point\""), 7u);
  EXPECT_EQ(occurrences_of(svg, "class=\"whisker\""), 0u);
  // A line per series through its points in x order: M then one L per further point.
  const std::regex line_re(R"re(<path class="line" d="M[0-9.]+,[0-9.]+((?: L[0-9.]+,[0-9.]+)*)")re");
  std::vector<std::size_t> segments;
  for (std::sregex_iterator it(svg.begin(), svg.end(), line_re), end; it != end; ++it)
    segments.push_back(occurrences_of((*it)[1].str(), " L"));
  EXPECT_EQ(segments, (std::vector<std::size_t>{2, 3}));
  // The unsorted series is drawn left to right.
  const std::regex xs_re(
      R"re(<path class="line" d="M([0-9.]+),[0-9.]+ L([0-9.]+),[0-9.]+ L([0-9.]+),[0-9.]+ L([0-9.]+))re");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, xs_re));
  EXPECT_LT(std::stod(m[1]), std::stod(m[2]));
  EXPECT_LT(std::stod(m[2]), std::stod(m[3]));
  EXPECT_LT(std::stod(m[3]), std::stod(m[4]));
  // Colours: the given one, and the palette's first for the series without one.
  EXPECT_NE(svg.find("stroke=\"#123456\""), std::string::npos);
  EXPECT_NE(svg.find("stroke=\"#1f77b4\""), std::string::npos);
}

TEST(LogLogPlot, DecadeTicksAxisTitlesAndLegend) {
  const std::string svg = loglog_plot_svg(plot(), two_series());
  // x spans 1e3..1e5 (two decades: 2 and 5 labelled too), y 0.018..2.76 ms -> 0.01..10.
  for (const char* label : {">1000<", ">10000<", ">100000<", ">2000<", ">50000<"})
    EXPECT_NE(svg.find(std::string("class=\"tick x-tick\" text-anchor=\"middle\"") + label), std::string::npos)
        << label;
  for (const char* label : {">0.01<", ">0.1<", ">1<", ">10<"})
    EXPECT_NE(svg.find(std::string("class=\"tick y-tick\" text-anchor=\"end\"") + label), std::string::npos) << label;
  EXPECT_EQ(occurrences_of(svg, "class=\"tick y-tick\""), 4u);  // three decades: no 2 and 5
  EXPECT_NE(svg.find(">N (lights)</text>"), std::string::npos);
  EXPECT_NE(svg.find("class=\"axis-title y-title\" text-anchor=\"middle\" transform=\"rotate(-90"), std::string::npos);
  EXPECT_NE(svg.find(">Filtered sampling over N</text>"), std::string::npos);
  EXPECT_EQ(occurrences_of(svg, "<text x=\"100.0\""), 3u);  // the legend labels, one a row
  EXPECT_NE(svg.find(">fis_tok15</text>"), std::string::npos);
  EXPECT_NE(svg.find(">fis_modified</text>"), std::string::npos);
}

TEST(LogLogPlot, ReferencePointsAreDrawnApartAndInTheLegend) {
  const std::string svg = loglog_plot_svg(plot(), two_series());
  EXPECT_EQ(occurrences_of(svg, "<path class=\"reference\" data-label=\"paper\""), 1u);
  EXPECT_NE(svg.find("<title>fis_tok15 (paper): x = 100000, 1.7 ms</title>"), std::string::npos);
  EXPECT_EQ(occurrences_of(svg, "class=\"legend-reference\""), 1u);
  EXPECT_NE(svg.find(">fis_tok15: paper</text>"), std::string::npos);
  // A reference outside the data widens the axes to hold it.
  auto far = two_series();
  far[1].references.push_back({1e7, 500, "paper", "custom tip"});
  const std::string wide = loglog_plot_svg(plot(), far);
  EXPECT_EQ(xml_problem(wide), "");
  EXPECT_NE(wide.find(">1e7<"), std::string::npos);
  EXPECT_NE(wide.find(">1e3<"), std::string::npos);  // one axis, one way of writing its labels
  EXPECT_EQ(wide.find(">100000<"), std::string::npos);
  EXPECT_NE(wide.find(">1000<"), std::string::npos);  // ms, now up to 1000
  EXPECT_NE(wide.find("<title>custom tip</title>"), std::string::npos);
  EXPECT_EQ(occurrences_of(wide, "class=\"legend-reference\""), 2u);
}

TEST(LogLogPlot, EscapesAllText) {
  const std::string nasty = "a<b&\"c\"";
  LogLogPlot p = plot();
  p.title = nasty;
  p.x_title = nasty;
  p.y_title = nasty;
  std::vector<LogLogSeries> s{{nasty, "red\"/><script>", {pt(1, 1), {2, 2, 1, 3, nasty}}, {{2, 1, nasty, ""}}}};
  const std::string svg = loglog_plot_svg(p, s);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(svg.find("a<b"), std::string::npos);
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  const std::string escaped = "a&lt;b&amp;&quot;c&quot;";
  EXPECT_NE(svg.find("aria-label=\"" + escaped + "\""), std::string::npos);
  EXPECT_NE(svg.find("<title>" + escaped + "</title>"), std::string::npos);
  EXPECT_NE(svg.find("data-series=\"" + escaped + "\""), std::string::npos);
  EXPECT_NE(svg.find("data-label=\"" + escaped + "\""), std::string::npos);
  EXPECT_NE(svg.find(">" + escaped + ": " + escaped + "</text>"), std::string::npos);  // the reference's legend entry
  EXPECT_GE(occurrences_of(svg, escaped), 9u);
}

TEST(LogLogPlot, SameInputSameBytes) {
  const std::string a = loglog_plot_svg(plot(), two_series());
  const std::string b = loglog_plot_svg(plot(), two_series());
  EXPECT_EQ(a, b);
  auto moved = two_series();
  moved[0].points[1].median *= 1.5;
  moved[0].points[1].q3 *= 1.5;
  EXPECT_NE(loglog_plot_svg(plot(), moved), a);
}

TEST(LogLogPlot, OnePointSeriesGetsAWhiskerInsteadOfALine) {
  const std::string svg = loglog_plot_svg(plot(), {{"single", "", {pt(500, 3)}, {}}});
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(occurrences_of(svg, "<path class=\"line\""), 0u);
  EXPECT_EQ(occurrences_of(svg, "<path class=\"band\""), 0u);
  EXPECT_EQ(occurrences_of(svg, "class=\"whisker\""), 1u);
  EXPECT_EQ(occurrences_of(svg, "<circle class=\"point\""), 1u);
  EXPECT_NE(svg.find("<title>single: x = 500, median 3 ms (q1 2.7, q3 3.6)</title>"), std::string::npos);
  // A value a decade apart from nothing still gets one full decade on each axis.
  EXPECT_NE(svg.find(">100<"), std::string::npos);
  EXPECT_NE(svg.find(">1000<"), std::string::npos);
}

TEST(LogLogPlot, RefusesWhatALogAxisCannotShow) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto draw = [](std::vector<LogLogSeries> s) { return loglog_plot_svg(plot(), s); };
  EXPECT_NE(input_error([&] { draw({}); }).find("no series to draw"), std::string::npos);
  EXPECT_NE(input_error([&] { draw({{"a", "", {}, {}}}); }).find("series 'a': no points"), std::string::npos);
  EXPECT_NE(input_error([&] {
              draw({{"a", "", {pt(0, 1)}, {}}});
            }).find("x = 0 cannot be placed on a log axis"),
            std::string::npos);
  EXPECT_NE(input_error([&] { draw({{"a", "", {pt(-2, 1)}, {}}}); }).find("x = -2"), std::string::npos);
  EXPECT_NE(input_error([&] { draw({{"a", "", {pt(nan, 1)}, {}}}); }).find("log axis"), std::string::npos);
  EXPECT_NE(input_error([&] { draw({{"a", "", {pt(1, 0)}, {}}}); }).find("at x = 1: median 0 ms"), std::string::npos);
  EXPECT_NE(input_error([&] {
              draw({{"a", "", {{1, 1, 0, 2, ""}}, {}}});
            }).find("q1 <= median <= q3"),
            std::string::npos);
  EXPECT_NE(input_error([&] {
              draw({{"a", "", {{1, 1, 1.1, 2, ""}}, {}}});
            }).find("q1 <= median <= q3"),
            std::string::npos);
  EXPECT_NE(input_error([&] {
              draw({{"a", "", {{1, 1, 0.5, 0.9, ""}}, {}}});
            }).find("q1 <= median <= q3"),
            std::string::npos);
  EXPECT_NE(input_error([&] {
              draw({{"a", "", {pt(4, 1), pt(4, 2)}, {}}});
            }).find("two points at x = 4"),
            std::string::npos);
  EXPECT_NE(input_error([&] {
              draw({{"a", "", {pt(4, 1)}, {{4, -1, "paper", ""}}}});
            }).find("reference 'paper' at x = 4, -1 ms cannot be placed"),
            std::string::npos);
  LogLogPlot tiny = plot();
  tiny.width = 100;
  EXPECT_NE(input_error([&] { loglog_plot_svg(tiny, two_series()); }).find("leave no room"), std::string::npos);
  EXPECT_EQ(input_error([&] { draw({}); }).rfind("log-log plot 'Filtered sampling over N': ", 0), 0u);
}

}  // namespace
}  // namespace vsgl
