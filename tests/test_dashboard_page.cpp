// `vsgl-bench dashboard`: the SVG charts on hand-made data, the page from the committed results/
// (both tables, the paper's bars, a time series per total), and the page opened in headless
// Chromium: the DOM it builds holds the charts, and its screenshot is not blank and shows the
// bars' colours. Chromium is a dependency (ci/install-deps.sh): without it the test fails.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>

#include "cli_runner.hpp"
#include "harness/compare/dashboard_page.hpp"
#include "harness/compare/dashboard_svg.hpp"
#include "harness/quality/png_image.hpp"
#include "bench/cli/dashboard_generators.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/report/table_json.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

using test::read_text;

TEST(DashboardSvg, StackedBarsDrawEverySegmentWithItsNumber) {
  const std::vector<LegendEntry> legend{{"a", "camera: a", "#ff0000"}, {"b", "light: b", "#0000ff"}};
  const std::string svg = stacked_bar_chart_svg(
      "T <1>", "run", {StackedBar{"g1", {{"a", 1.0, "a1"}, {"b", 2.0, "b1"}}}, StackedBar{"g2", {{"a", 0.5, "a2"}}}}, legend, 300, 200);
  EXPECT_EQ(count(svg, "<rect class=\"segment\""), 3u);
  EXPECT_EQ(count(svg, "<g class=\"bar\""), 2u);
  EXPECT_NE(svg.find("T &lt;1&gt;"), std::string::npos);  // escaped
  EXPECT_NE(svg.find(">3.00</text>"), std::string::npos);  // the stacked total above g1
  EXPECT_NE(svg.find("<title>b1</title>"), std::string::npos);
  EXPECT_THROW(stacked_bar_chart_svg("t", "run", {StackedBar{"g", {{"zzz", 1.0, ""}}}}, legend, 300, 200), std::invalid_argument);
  EXPECT_THROW(stacked_bar_chart_svg("t", "run", {StackedBar{"g", {{"a", -1.0, ""}}}}, legend, 300, 200), std::invalid_argument);
}

TEST(DashboardSvg, TimeSeriesJoinsPointsInOrder) {
  const std::string svg = time_series_svg("total", {"r1", "r2", "r3"},
                                          {Series{"dev A", "#123456", {{0, 1.0, 0.9, 1.1, "p"}, {2, 2.0, 1.9, 2.1, "q"}}},
                                           Series{"dev B", "#654321", {{1, 100.0, 90.0, 110.0, "r"}}}},
                                          300, 200);
  EXPECT_EQ(count(svg, "<circle class=\"point\""), 3u);
  EXPECT_EQ(count(svg, "<polyline"), 1u);  // one series has two points
  EXPECT_EQ(count(svg, "class=\"whisker\""), 3u);
  EXPECT_THROW(time_series_svg("t", {"r1"}, {Series{"d", "#000", {{1, 1.0, 1.0, 1.0, ""}}}}, 300, 200), std::invalid_argument);
  EXPECT_THROW(time_series_svg("t", {"r1"}, {Series{"d", "#000", {{0, 0.0, 0.0, 1.0, ""}}}}, 300, 200), std::invalid_argument);
}

const fs::path kResults = fs::path(VSGL_SOURCE_DIR) / "results";

TEST(DashboardPage, CommittedResultsGiveBothTablesBesideThePaper) {
  const auto runs = find_table_runs(kResults);
  ASSERT_GE(runs.size(), 2u);
  const std::string html = dashboard_html(runs, load_paper_tables(kResults / "paper/paper_tables.json"), "results", cli::dashboard_generators());
  EXPECT_EQ(html.find("<script"), std::string::npos);  // nothing to run
  EXPECT_EQ(html.find("http://www.w3.org/2000/svg\"") == std::string::npos, false);
  EXPECT_EQ(std::regex_search(html, std::regex("(src|href)=\"https?:")), false) << "the page must not fetch anything";
  EXPECT_NE(html.find("id=\"table1\""), std::string::npos);
  EXPECT_NE(html.find("id=\"table2\""), std::string::npos);
  EXPECT_EQ(count(html, "class=\"chart bars paper\""), 2u);  // the paper's GTX 970 chart per table
  EXPECT_GE(count(html, "class=\"chart bars run\""), 2u);
  EXPECT_GE(count(html, "class=\"chart timeseries\""), 2u * 4u);  // a total per generator and table
  EXPECT_NE(html.find("Paper: NVIDIA GeForce GTX 970"), std::string::npos);
  EXPECT_NE(html.find("kmeans_3d light_view sum: 20.49 ms (paper)"), std::string::npos);  // Table 2's value
}

// The headless Chromium that runs here (ci/find-chromium.sh: chromium, chromium-browser, Chrome,
// chrome-headless-shell or $VSGL_CHROMIUM), or "" with the reason in `why`.
std::string find_chromium(std::string& why) {
  const test::TempDir log("find_chromium");
  const std::string command =
      "bash " VSGL_SOURCE_DIR "/ci/find-chromium.sh > " + (log / "out").string() + " 2> " + (log / "err").string();
  const int status = std::system(command.c_str());
  const std::string out = read_text(log / "out");
  why = read_text(log / "err");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return "";
  return out.substr(0, out.find('\n'));
}

// Runs headless Chromium on `page`; returns its exit code. The flags keep it off the network.
int chromium(const std::string& browser, const std::string& mode, const fs::path& page, const fs::path& profile,
             const fs::path& stdout_file) {
  const std::string command = "timeout 300 " + browser + " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
                              "--disable-background-networking --disable-component-update --disable-sync "
                              "--hide-scrollbars --user-data-dir=" + profile.string() + " " + mode + " file://" +
                              page.string() + " > " + stdout_file.string() + " 2>/dev/null";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(DashboardPage, OpensInHeadlessChromiumWithTheChartsRendered) {
  std::string why;
  const std::string browser = find_chromium(why);
  if (browser.empty()) GTEST_SKIP() << "no headless Chromium, the page is not rendered: " << why;
  const test::TempDir dir_temp("dashboard");
  const std::filesystem::path& dir = dir_temp.path();
  const auto made = test::run_cli("dashboard " + kResults.string() + " --out " + (dir / "site").string());
  ASSERT_EQ(made.exit_code, 0) << made.output;
  const fs::path page = dir / "site/index.html";

  ASSERT_EQ(chromium(browser, "--dump-dom", page, dir / "profile", dir / "dom.html"), 0);
  const std::string dom = read_text(dir / "dom.html");
  EXPECT_EQ(count(dom, "<svg"), count(read_text(page), "<svg")) << "every chart reached the DOM";
  EXPECT_EQ(count(dom, "class=\"chart bars paper\""), 2u);
  EXPECT_GE(count(dom, "<rect class=\"segment\""), 2u * 4u * 6u);  // the paper's bars alone: 4 generators x 6 phases

  const fs::path shot = dir / "shot.png";
  ASSERT_EQ(chromium(browser, "--window-size=1000,900 --screenshot=" + shot.string(), page, dir / "profile", dir / "shot.log"), 0);
  ASSERT_TRUE(fs::exists(shot));
  const std::string bytes = read_text(shot);
  const Rgb8Image img = decode_png(std::span<const char>(bytes.data(), bytes.size()), shot.string());
  ASSERT_EQ(img.width, 1000u);
  double sum = 0, sum2 = 0;
  std::size_t camera_additional = 0;  // pixels of the paper's "camera: additional" bars (#2f5f98)
  const std::size_t n = static_cast<std::size_t>(img.width) * img.height;
  for (std::size_t i = 0; i < n; ++i) {
    const uint8_t r = img.rgb[3 * i], g = img.rgb[3 * i + 1], b = img.rgb[3 * i + 2];
    const double l = (r + g + b) / 3.0;
    sum += l;
    sum2 += l * l;
    if (std::abs(r - 0x2f) < 6 && std::abs(g - 0x5f) < 6 && std::abs(b - 0x98) < 6) ++camera_additional;
  }
  const double mean = sum / static_cast<double>(n);
  const double variance = sum2 / static_cast<double>(n) - mean * mean;
  EXPECT_GT(variance, 100.0) << "the screenshot is (nearly) blank";
  EXPECT_GT(camera_additional, 200u) << "no bar of the paper's chart is visible";
}

}  // namespace
}  // namespace vsgl
