// `vsgl-bench dashboard`: the SVG charts on hand-made data, the page from the committed results/
// (both tables, the paper's bars, a time series per total), and the page opened in headless
// Chromium: the DOM it builds holds the charts, and its screenshot is not blank and shows the
// bars' colours; and the scaling section from synthetic sweep JSON beside the committed tables
// (a log-log chart per axis, the fits, the flagged ones marked, the claims), a broken sweep named,
// no sweep in one line. Chromium is a dependency (ci/install-deps.sh): without it the rendering
// tests are skipped, saying why.
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
#include "input_error.hpp"
#include "synthetic_frame.hpp"
#include "synthetic_sweep.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

using test::read_text;

TEST(DashboardSvg, StackedBarsDrawEverySegmentWithItsNumber) {
  const std::vector<LegendEntry> legend{{"a", "camera: a", "#ff0000"}, {"b", "light: b", "#0000ff"}};
  const std::string svg = stacked_bar_chart_svg(
      "T <1>", "run", {StackedBar{"g1", {{"a", 1.0, "a1"}, {"b", 2.0, "b1"}}}, StackedBar{"g2", {{"a", 0.5, "a2"}}}}, legend, 300, 200);
  EXPECT_EQ(occurrences(svg, "<rect class=\"segment\""), 3u);
  EXPECT_EQ(occurrences(svg, "<g class=\"bar\""), 2u);
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
  EXPECT_EQ(occurrences(svg, "<circle class=\"point\""), 3u);
  EXPECT_EQ(occurrences(svg, "<polyline"), 1u);  // one series has two points
  EXPECT_EQ(occurrences(svg, "class=\"whisker\""), 3u);
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
  EXPECT_EQ(occurrences(html, "class=\"chart bars paper\""), 2u);  // the paper's GTX 970 chart per table
  EXPECT_GE(occurrences(html, "class=\"chart bars run\""), 2u);
  EXPECT_GE(occurrences(html, "class=\"chart timeseries\""), 2u * 4u);  // a total per generator and table
  EXPECT_NE(html.find("Paper: NVIDIA GeForce GTX 970"), std::string::npos);
  EXPECT_NE(html.find("kmeans_3d light_view sum: 20.49 ms (paper)"), std::string::npos);  // Table 2's value
}

// A results directory: the committed tables under their paths, and each sweep document at its path.
void make_results(const fs::path& dir, const std::vector<std::pair<std::string, nlohmann::ordered_json>>& sweeps,
                  bool with_tables = true) {
  if (with_tables)
    for (const BenchRun& r : find_table_runs(kResults)) {
      fs::create_directories((dir / r.path).parent_path());
      fs::copy_file(kResults / r.path, dir / r.path);
    }
  for (const auto& [path, doc] : sweeps) {
    fs::create_directories((dir / path).parent_path());
    std::ofstream(dir / path) << doc.dump(1);
  }
}

// Two sweeps of the tiny scene: N on FIS and k-means (written second, dated first), and the PDF
// sharpness γ = 0, 1, 2 with its claims (γ = 0 stays off the log axis).
std::vector<std::pair<std::string, nlohmann::ordered_json>> two_sweeps() {
  const std::vector<std::string> generators{"fis_modified", "kmeans_3d"};
  nlohmann::ordered_json gamma =
      test::synthetic_sweep_json(test::synthetic_sweep({parse_axis_spec("pdf-sharpness=0,1,2")}, generators),
                                 test::synthetic_sweep_context("GPU <&> \"B\"", "2026-03-01T00:00:00Z"));
  gamma["claims"] =
      nlohmann::ordered_json::array({test::synthetic_sweep_claim(false, "kmeans_3d moves less than the <band>")});
  return {
      {"a/sweep.json", gamma},
      {"b/sweep.json", test::synthetic_sweep_json(test::synthetic_sweep({parse_axis_spec("vsgls=8:32:x2")}, generators),
                                                  test::synthetic_sweep_context("GPU A", "2026-02-01T00:00:00Z"))}};
}

std::string between(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t a = text.find(from);
  if (a == std::string::npos) return "";
  const std::size_t b = text.find(to, a + from.size());
  return text.substr(a, b == std::string::npos ? std::string::npos : b - a);
}

TEST(DashboardPage, ScalingSectionDrawsEachSweepAxisWithItsFits) {
  const test::TempDir dir("dashboard_scaling");
  make_results(dir.path(), two_sweeps());
  const auto runs = find_table_runs(dir.path());
  EXPECT_EQ(runs.size(), find_table_runs(kResults).size()) << "sweep.json is not read as a table run";
  const auto sweeps = find_sweep_runs(dir.path());
  ASSERT_EQ(sweeps.size(), 2u);
  EXPECT_EQ(sweeps[0].path, "b/sweep.json");  // one scene: by date
  EXPECT_EQ(sweeps[1].path, "a/sweep.json");
  const std::string html = dashboard_html(runs, load_paper_tables(kResults / "paper/paper_tables.json"), "results",
                                          cli::dashboard_generators(), sweeps);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(std::regex_search(html, std::regex("(src|href)=\"https?:")), false) << "the page must not fetch anything";
  EXPECT_NE(html.find("id=\"table1\""), std::string::npos);  // the tables stay
  ASSERT_NE(html.find("<section class=\"scaling\" id=\"scaling\">"), std::string::npos);
  EXPECT_EQ(html.find("class=\"no-sweep\""), std::string::npos);
  EXPECT_EQ(occurrences(html, "<section class=\"sweep\""), 2u);
  EXPECT_EQ(occurrences(html, "class=\"chart loglog\""), 2u);  // one plot per axis

  const std::string n = between(html, "id=\"sweep1\"", "id=\"sweep2\"");
  EXPECT_NE(n.find("tiny, procedural: GPU A, 2026-02-01, commit 0123456 (quick)"), std::string::npos) << n;
  EXPECT_NE(n.find("<code>b/sweep.json</code>"), std::string::npos);
  EXPECT_EQ(occurrences(n, "<g class=\"series\""), 4u);  // a series per generator and view
  for (const char* s :
       {"fis_modified camera_view", "fis_modified light_view", "kmeans_3d camera_view", "kmeans_3d light_view"})
    EXPECT_EQ(occurrences(n, std::string("data-series=\"") + s + "\""), 1u) << s;
  EXPECT_EQ(occurrences(n, "<circle class=\"point\""), 4u * 3u);
  EXPECT_NE(n.find("cost \u221d N^1.00 ["), std::string::npos);  // FIS camera filtered sampling
  EXPECT_NE(n.find("cost \u221d N^2.00 ["), std::string::npos);  // the light view's, flagged
  EXPECT_GE(occurrences(n, "<tr class=\"flagged\">"), 1u);
  EXPECT_NE(n.find("<strong>faster</strong>"), std::string::npos);
  EXPECT_NE(n.find("<td>filtered_sampling</td><td class=\"growth\">cost \u221d N^2.00"), std::string::npos);
  EXPECT_NE(n.find("fit(s) exclude the growth"), std::string::npos);
  EXPECT_EQ(n.find("class=\"claims\""), std::string::npos);  // no claims in this file

  const std::string g = between(html, "id=\"sweep2\"", "</section>");
  EXPECT_NE(g.find("GPU &lt;&amp;&gt; &quot;B&quot;"), std::string::npos) << "escaped";
  EXPECT_EQ(html.find("GPU <&>"), std::string::npos);
  EXPECT_EQ(occurrences(g, "<circle class=\"point\""), 4u * 2u) << "gamma = 0 is off the log axis";
  EXPECT_NE(g.find("<th>pdf-sharpness=0 *</th>"), std::string::npos) << "but in the table";
  EXPECT_EQ(occurrences(between(g, "class=\"sweep-totals\"", "</table>"), "<tr>"), 1u + 4u);
  EXPECT_NE(g.find("class=\"claims\""), std::string::npos);
  EXPECT_NE(g.find("<td>pdf_independence</td>"), std::string::npos);
  EXPECT_NE(g.find("does not hold"), std::string::npos);
  EXPECT_NE(g.find("moves less than the &lt;band&gt;"), std::string::npos);
}

// A sweep.json written while its run went on (DESIGN.md §10.1) is drawn from the points it has,
// and marked: in its heading and in a line that says what is missing.
TEST(DashboardPage, AnIncompleteSweepIsMarkedAndStillDrawn) {
  const test::TempDir dir("dashboard_incomplete_sweep");
  MeasuredSweep s = test::synthetic_sweep({parse_axis_spec("vsgls=8:64:x2")}, {"fis_modified"});
  s.points.resize(2);
  s.complete = false;
  auto sweeps = two_sweeps();
  sweeps.emplace_back("c/sweep.json", test::synthetic_sweep_json(s, test::synthetic_sweep_context("GPU C")));
  make_results(dir.path(), sweeps, false);
  const auto runs = find_sweep_runs(dir.path());
  ASSERT_EQ(runs.size(), 3u);
  const std::string html = scaling_section_html(runs, "results");
  EXPECT_EQ(occurrences(html, "<section class=\"sweep\""), 3u);
  EXPECT_EQ(occurrences(html, "class=\"incomplete\""), 2u) << "the heading and the line of one sweep only";
  const std::string c = between(html, "GPU C", "</section>");
  EXPECT_NE(c.find("<span class=\"incomplete\">incomplete: 2 of 4 points</span></h3>"), std::string::npos) << c;
  EXPECT_NE(c.find("after 2 of 4 points"), std::string::npos) << c;
  EXPECT_NE(c.find("(2 points)"), std::string::npos) << c;
  EXPECT_EQ(occurrences(c, "class=\"chart loglog\""), 1u);
  EXPECT_EQ(occurrences(c, "<circle class=\"point\""), 2u * 2u);  // two points of each view's series
  EXPECT_NE(c.find("cost \u221d N^"), std::string::npos) << "fitted over the two points";
}

// A table document of a capture that is not one of the paper's (`tables --capture DIR` on a user's
// glTF scene writes OUT/<scene>.json, "table": null), made from a committed table.
nlohmann::ordered_json user_scene_table(const std::string& scene) {
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(read_text(kResults / "lavapipe/table1.json"));
  doc["table"] = nullptr;
  doc["scene"] = nlohmann::ordered_json{{"name", scene},
                                        {"kind", "user"},
                                        {"model_file", "room/room.gltf"},
                                        {"content_hash", "fnv1a64:0123456789abcdef"},
                                        {"triangles", 1234}};
  return doc;
}

// Every table document under the folder is drawn, known by its content whatever its file is named:
// a user's scene gets its own section (its runs' phases and totals, no paper beside them), other
// JSON is left alone, and `dashboard` on a folder of such a table alone succeeds.
TEST(DashboardPage, AUserSceneTableIsDrawnInASectionOfItsOwn) {
  const test::TempDir dir("dashboard_user_scene");
  make_results(dir.path(), {});
  fs::create_directories(dir.path() / "mine");
  std::ofstream(dir.path() / "mine/my_room.json") << user_scene_table("my_room").dump(1);
  std::ofstream(dir.path() / "mine/notes.json") << "{not JSON";  // not a table document: skipped
  std::ofstream(dir.path() / "mine/list.json") << "[1, 2, 3]";   // neither
  const auto runs = find_table_runs(dir.path());
  ASSERT_EQ(runs.size(), find_table_runs(kResults).size() + 1);
  const BenchRun& user = runs.back();  // after the paper's tables
  EXPECT_EQ(user.path, "mine/my_room.json");
  ASSERT_TRUE(user.tables.contains(0));
  EXPECT_NE(user.find("my_room/fis_modified/total"), nullptr);
  const std::string html = dashboard_html(runs, load_paper_tables(kResults / "paper/paper_tables.json"), "results",
                                          cli::dashboard_generators());
  EXPECT_NE(html.find("id=\"table1\""), std::string::npos);  // the paper's tables stay
  const std::string section = between(html, "id=\"scene-my-room\"", "</section>");
  ASSERT_FALSE(section.empty()) << "no section of the user's scene";
  EXPECT_NE(section.find("my_room, user"), std::string::npos) << section.substr(0, 400);
  EXPECT_EQ(occurrences(section, "class=\"chart bars run\""), 1u);
  EXPECT_EQ(occurrences(section, "class=\"chart bars paper\""), 0u) << "no paper numbers beside a user's scene";
  EXPECT_EQ(occurrences(section, "class=\"chart timeseries\""), 4u);      // a total per generator
  EXPECT_NE(html.find("<td>mine/my_room.json</td>"), std::string::npos);  // in the list of runs

  // `compare` and `export` key runs by paper table: they refuse it, saying who reads it.
  const std::string refused = test::input_error([&] { load_bench_run(dir.path() / "mine/my_room.json"); });
  EXPECT_NE(refused.find("dashboard draws it"), std::string::npos) << refused;

  // The command, on the folder `tables --capture DIR --out OUT` would leave.
  const test::TempDir only("dashboard_user_scene_only");
  std::ofstream(only.path() / "my_room.json") << user_scene_table("my_room").dump(1);
  const fs::path site = only.path() / "site";
  const test::CliResult r = test::run_cli("dashboard " + only.path().string() + " --out " + site.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(read_text(site / "index.html").find("id=\"scene-my-room\""), std::string::npos);
}

TEST(DashboardPage, ScalingSectionSaysInOneLineThatThereIsNoSweep) {
  const std::string html =
      dashboard_html(find_table_runs(kResults), load_paper_tables(kResults / "paper/paper_tables.json"), "results",
                     cli::dashboard_generators(), {});
  const std::string section = between(html, "<section class=\"scaling\"", "</section>");
  ASSERT_FALSE(section.empty());
  EXPECT_EQ(occurrences(section, "<p"), 1u);
  EXPECT_NE(section.find("No sweep JSON"), std::string::npos) << section;
  EXPECT_EQ(occurrences(section, "<svg"), 0u);
}

// A frame.json under the directory (`vsgl-bench frame`, DESIGN.md §9.2) gives the frame section: one
// chart, a stacked bar per generator with a segment per phase, each with its number; without one,
// the section says so. `dashboard` finds it by content, also where it is the only document.
TEST(DashboardPage, AFrameJsonIsDrawnAsAStackedBarPerGeneratorOfTheFivePhases) {
  const test::TempDir temp("dashboard_frame");
  fs::create_directories(temp.path() / "run" / "tiny");
  const FrameModel model = test::synthetic_frame();
  std::ofstream(temp.path() / "run" / "tiny" / "frame.json") << to_json(model).dump(2) << "\n";
  const auto frames = find_frame_runs(temp.path());
  ASSERT_EQ(frames.size(), 1u);
  const std::string html =
      dashboard_html(find_table_runs(kResults), load_paper_tables(kResults / "paper/paper_tables.json"), "results",
                     cli::dashboard_generators(), {}, frames);
  const std::string section = between(html, "<section class=\"frame\"", "</section>");
  ASSERT_FALSE(section.empty());
  EXPECT_EQ(occurrences(section, "<svg"), 1u);
  EXPECT_EQ(occurrences(section, "class=\"bar\""), model.generators.size()) << section;
  for (const auto& g : model.generators)
    for (const auto& p : g.phases)
      EXPECT_NE(section.find(g.name + " " + p.phase + ": median "), std::string::npos) << g.name << " " << p.phase;
  const std::string none =
      between(dashboard_html(find_table_runs(kResults), load_paper_tables(kResults / "paper/paper_tables.json"),
                             "results", cli::dashboard_generators(), {}),
              "<section class=\"frame\"", "</section>");
  EXPECT_NE(none.find("No frame JSON"), std::string::npos) << none;
  EXPECT_EQ(occurrences(none, "<svg"), 0u);
  const auto r = test::run_cli_without_vulkan("dashboard " + (temp.path() / "run").string() + " --out " +
                                              (temp.path() / "site").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string page = read_text(temp.path() / "site" / "index.html");
  EXPECT_NE(page.find("<section class=\"frame\""), std::string::npos);
  EXPECT_NE(page.find("kmeans vsgl_generation: median "), std::string::npos);
}

TEST(DashboardPage, TheCommittedSweepsLoadAndEachHasItsScalingSection) {
  const auto sweeps = find_sweep_runs(kResults);
  ASSERT_FALSE(sweeps.empty()) << "results/lavapipe/sweep/ is committed";
  const std::string html =
      dashboard_html(find_table_runs(kResults), load_paper_tables(kResults / "paper/paper_tables.json"), "results",
                     cli::dashboard_generators(), sweeps);
  const std::string section = between(html, "<section class=\"scaling\"", "</section>");
  EXPECT_EQ(section.find("No sweep JSON"), std::string::npos);
  EXPECT_GE(occurrences(html, "<svg"), sweeps.size());
  EXPECT_NE(html.find("<code>lavapipe/sweep/vsgls/sweep.json</code>"), std::string::npos);
  // Written before "complete" existed: read as complete, no mark.
  for (const SweepRun& r : sweeps) EXPECT_TRUE(r.model.complete) << r.path;
  EXPECT_EQ(section.find("class=\"incomplete\""), std::string::npos);
}

TEST(DashboardPage, ABrokenSweepIsAnErrorNamingIt) {
  const test::TempDir dir("dashboard_broken_sweep");
  auto sweeps = two_sweeps();
  sweeps[1].second["fits"][0].erase("verdict");
  make_results(dir.path(), sweeps, false);
  const std::string m = test::input_error([&] { find_sweep_runs(dir.path()); });
  EXPECT_NE(m.find((dir / "b/sweep.json").generic_string()), std::string::npos) << m;
  EXPECT_NE(m.find("/fits/0/verdict: missing field"), std::string::npos) << m;
  std::ofstream(dir / "b/sweep.json") << "{";
  EXPECT_NE(test::input_error([&] { find_sweep_runs(dir.path()); }).find((dir / "b/sweep.json").generic_string()),
            std::string::npos);
  const auto made = test::run_cli("dashboard " + dir.path().string() + " --out " + (dir / "site").string());
  EXPECT_EQ(made.exit_code, 3) << made.output;
  EXPECT_NE(made.output.find("b/sweep.json"), std::string::npos) << made.output;
}

// std::system's status as an exit code (-1: killed); Windows gives the code itself.
int exit_code(int status) {
#ifdef _WIN32
  return status;
#else
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
#endif
}

// The headless Chromium that runs here (ci/find-chromium.sh: chromium, chromium-browser, Chrome,
// chrome-headless-shell or $VSGL_CHROMIUM), or "" with the reason in `why`.
std::string find_chromium(std::string& why) {
#ifdef _WIN32
  why = "the browser check runs in the host's build (ci/find-chromium.sh is a bash script)";
  return "";
#endif
  const test::TempDir log("find_chromium");
  const std::string command =
      "bash " VSGL_SOURCE_DIR "/ci/find-chromium.sh > " + (log / "out").string() + " 2> " + (log / "err").string();
  const int status = std::system(command.c_str());
  const std::string out = read_text(log / "out");
  why = read_text(log / "err");
  if (exit_code(status) != 0) return "";
  return out.substr(0, out.find('\n'));
}

// Runs headless Chromium on `page`; returns its exit code. The flags keep it off the network.
int chromium(const std::string& browser, const std::string& mode, const fs::path& page, const fs::path& profile,
             const fs::path& stdout_file) {
  const std::string command = "timeout 300 " + browser + " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
                              "--disable-background-networking --disable-component-update --disable-sync "
                              "--hide-scrollbars --user-data-dir=" + profile.string() + " " + mode + " file://" +
                              page.string() + " > " + stdout_file.string() + " 2>/dev/null";
  return exit_code(std::system(command.c_str()));
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
  EXPECT_EQ(occurrences(dom, "<svg"), occurrences(read_text(page), "<svg")) << "every chart reached the DOM";
  EXPECT_EQ(occurrences(dom, "class=\"chart bars paper\""), 2u);
  EXPECT_GE(occurrences(dom, "<rect class=\"segment\""),
            2u * 4u * 6u);  // the paper's bars alone: 4 generators x 6 phases

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

// A results directory of sweeps alone: the page opens with the scaling section, every log-log
// chart reaches the DOM, and the first series' colour (series_color(0)) is on the screenshot.
TEST(DashboardPage, OpensInHeadlessChromiumWithTheScalingSectionRendered) {
  std::string why;
  const std::string browser = find_chromium(why);
  if (browser.empty()) GTEST_SKIP() << "no headless Chromium, the page is not rendered: " << why;
  const test::TempDir dir_temp("dashboard_scaling_chromium");
  const fs::path& dir = dir_temp.path();
  make_results(dir / "results", two_sweeps(), false);
  const auto made = test::run_cli("dashboard " + (dir / "results").string() + " --out " + (dir / "site").string());
  ASSERT_EQ(made.exit_code, 0) << made.output;
  EXPECT_NE(made.output.find("(0 table runs, 2 sweep files, 0 frame files)"), std::string::npos) << made.output;
  const fs::path page = dir / "site/index.html";
  const std::string html = read_text(page);
  ASSERT_EQ(occurrences(html, "class=\"chart loglog\""), 2u);

  ASSERT_EQ(chromium(browser, "--dump-dom", page, dir / "profile", dir / "dom.html"), 0);
  const std::string dom = read_text(dir / "dom.html");
  EXPECT_EQ(occurrences(dom, "class=\"chart loglog\""), 2u) << "every chart reached the DOM";
  EXPECT_EQ(occurrences(dom, "<g class=\"series\""), occurrences(html, "<g class=\"series\""));
  EXPECT_EQ(occurrences(dom, "<tr class=\"flagged\">"), occurrences(html, "<tr class=\"flagged\">"));
  EXPECT_GE(occurrences(dom, "<tr class=\"flagged\">"), 1u);

  const fs::path shot = dir / "shot.png";
  ASSERT_EQ(chromium(browser, "--window-size=1000,1200 --screenshot=" + shot.string(), page, dir / "profile",
                     dir / "shot.log"),
            0);
  ASSERT_TRUE(fs::exists(shot));
  const std::string bytes = read_text(shot);
  const Rgb8Image img = decode_png(std::span<const char>(bytes.data(), bytes.size()), shot.string());
  std::size_t first_series = 0;  // pixels of #1f77b4: the first series' line, markers and legend
  const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
  for (std::size_t i = 0; i < pixels; ++i) {
    const uint8_t r = img.rgb[3 * i], g = img.rgb[3 * i + 1], b = img.rgb[3 * i + 2];
    if (std::abs(r - 0x1f) < 12 && std::abs(g - 0x77) < 12 && std::abs(b - 0xb4) < 12) ++first_series;
  }
  EXPECT_GT(first_series, 50u) << "no series of the scaling chart is visible";
}

}  // namespace
}  // namespace vsgl
