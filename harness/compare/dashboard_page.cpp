#include "harness/compare/dashboard_page.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <tuple>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "harness/compare/dashboard_svg.hpp"
#include "harness/compare/svg_markup.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/path_text.hpp"

namespace vsgl {
namespace {

const char* const kViews[] = {"camera_view", "light_view"};

// Bar labels must fit under a bar.
using Generators = std::vector<DashboardGenerator>;

std::string short_generator(const Generators& generators, const std::string& g) {
  for (const auto& d : generators)
    if (d.name == g) return d.short_label;
  return g;  // a run of a generator this build does not know
}

// One hue per phase; the light view a lighter tint of the camera view's.
std::string phase_color(const std::string& view, const std::string& phase) {
  static const std::map<std::string, std::pair<std::string, std::string>> colors{
      {"additional", {"#2f5f98", "#8fb3dd"}},         {"mipmapping", {"#3b8a3e", "#9fd39f"}},
      {"filtered_sampling", {"#d9781a", "#f6c38f"}},  {"cluster_assignment", {"#6a3d9a", "#c2a5de"}},
      {"sort", {"#b8860b", "#ecd27a"}},               {"sum", {"#b22222", "#ee9a9a"}}};
  const auto it = colors.find(phase);
  if (it == colors.end()) return view == "camera_view" ? "#555555" : "#aaaaaa";
  return view == "camera_view" ? it->second.first : it->second.second;
}

std::string view_short(const std::string& view) { return view == "camera_view" ? "camera" : "light"; }

std::string day(const std::string& date) { return date.substr(0, std::min<std::size_t>(date.size(), 10)); }

std::string short_commit(const std::string& commit) {
  return commit == "unknown" ? "(no commit)" : commit.substr(0, std::min<std::size_t>(commit.size(), 7));
}

// A chart section: a paper table, or (table 0) the table of one capture that is not the paper's,
// known by its scene's name.
struct Section {
  int table = 0;
  std::string scene;  // table 0 only

  bool operator==(const Section&) const = default;
};

std::string scene_name_of(const BenchRun& r, int table) {
  const auto t = r.tables.find(table);
  return t != r.tables.end() && t->second.scene ? t->second.scene->name : "";
}

Section section_of(const BenchRun& r, int table) { return Section{table, table == 0 ? scene_name_of(r, 0) : ""}; }

bool in_section(const BenchRun& r, const Section& section) {
  return r.tables.contains(section.table) && section_of(r, section.table) == section;
}

// The stable names' first part (regression_run.hpp): "table1/", or "<scene>/" for table 0.
std::string series_prefix(const Section& section) {
  return section.table != 0 ? "table" + std::to_string(section.table) + "/" : section.scene + "/";
}

std::string section_id(const Section& section) {
  if (section.table != 0) return "table" + std::to_string(section.table);
  std::string id = "scene-";
  for (const char c : section.scene) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return id;
}

// A run's scene of a table: each chart and series says which scene it timed.
std::string scene_of(const BenchRun& r, int table) {
  const auto t = r.tables.find(table);
  return t != r.tables.end() && t->second.scene ? scene_label(*t->second.scene) : "scene not recorded";
}

std::string run_title(const BenchRun& r, int table) {
  std::string s = r.device + ", " + day(r.date) + ", " + scene_of(r, table);
  if (r.quick) s += " (quick)";
  if (!r.altered_generators.empty()) s += " (altered timings: not a measurement)";
  return s;
}

std::string altered_text(const BenchRun& r) {
  std::string s = "altered timings (not a measurement):";
  for (const auto& g : r.altered_generators) s += " " + g;
  return s;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

void add_legend(std::vector<LegendEntry>& legend, std::set<std::string>& seen, const std::string& view, const std::string& phase) {
  const std::string key = view + "/" + phase;
  if (seen.insert(key).second) legend.push_back(LegendEntry{key, view_short(view) + ": " + phase, phase_color(view, phase)});
}

// The measured chart of one run of one table.
std::string run_bars(const BenchRun& run, int table, const Generators& generators) {
  std::vector<StackedBar> bars;
  std::vector<LegendEntry> legend;
  std::set<std::string> seen;
  std::vector<std::string> timed;
  for (const RunSeries& s : run.series)
    if (s.table == table && std::find(timed.begin(), timed.end(), s.generator) == timed.end())
      timed.push_back(s.generator);
  for (const auto& g : timed) {
    StackedBar bar{short_generator(generators, g), {}};
    for (const char* view : kViews)
      for (const RunSeries& s : run.series)
        if (s.table == table && s.generator == g && s.view == view && !s.is_total()) {
          add_legend(legend, seen, view, s.phase);
          bar.segments.push_back(BarSegment{std::string(view) + "/" + s.phase, s.median_ms,
                                            g + " " + view + " " + s.phase + ": median " + fmt(s.median_ms) + " ms (q1 " +
                                                fmt(s.q1_ms) + ", q3 " + fmt(s.q3_ms) + ", " +
                                                std::to_string(s.samples_ms.size()) + " samples)"});
        }
    bars.push_back(std::move(bar));
  }
  return stacked_bar_chart_svg(run_title(run, table), "run", bars, legend, 460, 330);
}

// The paper's chart of one table (the generators the paper timed).
std::string paper_bars(const nlohmann::ordered_json& paper, int table, const Generators& generators) {
  const nlohmann::ordered_json& t = paper.at("tables").at(std::to_string(table));
  std::vector<StackedBar> bars;
  std::vector<LegendEntry> legend;
  std::set<std::string> seen;
  // The paper's column order.
  for (const DashboardGenerator& d : generators) {
    if (!d.in_paper) continue;
    const std::string& g = d.name;
    if (!t.contains(g)) continue;
    StackedBar bar{short_generator(generators, g), {}};
    for (const char* view : kViews) {
      // The phases in execution order, whatever the file's order. A phase the paper's
      // file does not give is left out of its bar (the file is validated for shape, not for
      // which phases each generator has).
      const nlohmann::ordered_json& phases = t.at(g).at(view);
      for (const auto& phase : d.phases) {
        if (!phases.contains(phase)) continue;
        const double ms = phases.at(phase).get<double>();
        add_legend(legend, seen, view, phase);
        bar.segments.push_back(BarSegment{std::string(view) + "/" + phase, ms,
                                          g + " " + view + " " + phase + ": " + fmt(ms) + " ms (paper)"});
      }
    }
    bars.push_back(std::move(bar));
  }
  return stacked_bar_chart_svg("Paper: " + paper.at("setup").at("gpu").get<std::string>(), "paper", bars, legend, 460, 330);
}

std::string series_key(const BenchRun& r, int table) { return r.device + " (" + scene_of(r, table) + ")"; }

// One series per device and scene: a stand-in's totals never share a line with the paper scene's.
std::string total_series(const std::vector<const BenchRun*>& runs, int table, const std::string& generator,
                         const std::map<std::string, std::string>& series_colors) {
  std::vector<std::string> labels;
  for (const BenchRun* r : runs) labels.push_back(day(r->date) + " " + short_commit(r->git_commit));
  std::map<std::string, Series> by_key;
  std::vector<std::string> order;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunSeries* s = runs[i]->find(series_prefix(section_of(*runs[i], table)) + generator + "/total");
    if (s == nullptr) continue;
    const std::string key = series_key(*runs[i], table);
    auto [it, fresh] = by_key.try_emplace(key);
    if (fresh) {
      it->second.name = key;
      it->second.color = series_colors.at(key);
      order.push_back(key);
    }
    it->second.points.push_back(
        SeriesPoint{i, s->median_ms, std::min(s->q1_ms, s->median_ms), std::max(s->q3_ms, s->median_ms),
                    key + " " + runs[i]->date + " commit " + runs[i]->git_commit + ": median " + fmt(s->median_ms) +
                        " ms (q1 " + fmt(s->q1_ms) + ", q3 " + fmt(s->q3_ms) + ")"});
  }
  std::vector<Series> series;
  for (const auto& k : order) series.push_back(by_key.at(k));
  return time_series_svg(generator + " total", labels, series, 300, 200 + 14 * static_cast<int>(series.size()));
}

}  // namespace

namespace {

// The frame section: per frame run, a stacked bar per generator of the five phases (DESIGN.md §9.2).
std::string frame_section_html(const std::vector<FrameRun>& frames, const std::string& source) {
  static const char* const kPhaseColors[] = {"#9e9e9e", "#8c6bb1", "#2b8cbe", "#41ab5d", "#fd8d3c"};
  std::ostringstream os;
  os << "<section class=\"frame\" id=\"frame\">\n<h2>The frame (<code>vsgl-bench frame</code>)</h2>\n";
  if (frames.empty()) {
    os << "<p>No frame JSON (the output of <code>frame</code>) under <code>" << xml_escape(source) << "</code>.</p>\n";
    return os.str() + "</section>\n";
  }
  os << "<p class=\"note\">Per generator the paper's frame phase by phase, median ms; <code>rsm_replay</code> "
        "copies the recorded RSM (a replay, not the paper's RSM rendering).</p>\n<div class=\"charts\">\n";
  const auto& names = frame_phase_names();
  std::vector<LegendEntry> legend;
  for (std::size_t p = 0; p < names.size(); ++p) legend.push_back(LegendEntry{names[p], names[p], kPhaseColors[p % 5]});
  for (const FrameRun& f : frames) {
    const FrameModel& m = f.model;
    std::vector<StackedBar> bars;
    for (const FrameGeneratorTiming& g : m.generators) {
      StackedBar bar{g.name, {}};
      for (std::size_t p = 0; p < g.phases.size(); ++p) {
        const TimingStatistics& s = g.phases[p].stats;
        bar.segments.push_back(BarSegment{g.phases[p].phase, s.median_ms,
                                          g.name + " " + g.phases[p].phase + ": median " + fmt(s.median_ms) +
                                              " ms (q1 " + fmt(s.q1_ms) + ", q3 " + fmt(s.q3_ms) + "), " +
                                              fmt(100 * frame_phase_share(g, p)) + " % of the frame"});
      }
      bars.push_back(std::move(bar));
    }
    const std::string title = m.capture.scene + " on " + m.device.name + ", " + day(m.run.started_utc) +
                              (m.config.paper_sizes ? "" : " (not the paper's sizes)") +
                              (m.run.quick ? " --quick" : "");
    os << stacked_bar_chart_svg(title, "frame", bars, legend, 460, 330) << "\n";
  }
  os << "</div>\n";
  return os.str() + "</section>\n";
}

}  // namespace

std::vector<FrameRun> find_frame_runs(const std::filesystem::path& results_dir) {
  std::vector<FrameRun> out;
  std::error_code ec;
  if (!std::filesystem::is_directory(results_dir, ec)) return out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(results_dir)) {
    if (!e.is_regular_file() || e.path().extension() != ".json") continue;
    nlohmann::ordered_json doc;
    try {
      doc = read_json_file(e.path(), "a results file");
    } catch (const InputError&) {
      continue;  // not JSON: no frame document (find_table_runs speaks for the tables)
    }
    if (!doc.is_object() || !doc.contains("kind") || doc["kind"] != "frame") continue;
    const std::string path = path_text(e.path());
    out.push_back(FrameRun{path, frame_model_from_json(doc, path)});
  }
  std::sort(out.begin(), out.end(), [](const FrameRun& a, const FrameRun& b) { return a.path < b.path; });
  return out;
}

std::vector<BenchRun> find_table_runs(const std::filesystem::path& results_dir) {
  if (!std::filesystem::is_directory(results_dir)) throw InputError(path_text(results_dir) + ": not a directory");
  std::vector<BenchRun> runs;
  for (const auto& e : std::filesystem::recursive_directory_iterator(results_dir)) {
    const std::filesystem::path& file = e.path();
    if (!e.is_regular_file() || file.extension() != ".json") continue;
    const std::string relative = std::filesystem::relative(file, results_dir).generic_string();  // '/' on every host
    // Known by content, not by name: a user scene's table is OUT/<scene>.json. A file named like a
    // paper table's must read; any other JSON that is no table document is not the dashboard's.
    nlohmann::ordered_json doc;
    if (is_table_file_name(file.filename().string())) {
      doc = read_json_file(file, "the run");
    } else {
      std::ifstream in(file, std::ios::binary);
      doc = nlohmann::ordered_json::parse(in, nullptr, false);
      if (doc.is_discarded() || !is_table_document(doc)) continue;
    }
    BenchRun r = parse_bench_run(doc, path_text(file), CaptureTables::kRead);
    r.path = relative;
    if (r.format == "table") runs.push_back(std::move(r));
  }
  // The paper's tables first (1, 2), then the other captures' by scene; each by date, commit, path.
  std::sort(runs.begin(), runs.end(), [](const BenchRun& a, const BenchRun& b) {
    const int ta = a.tables.begin()->first, tb = b.tables.begin()->first;
    const bool ua = ta == 0, ub = tb == 0;
    const std::string sa = scene_name_of(a, ta), sb = scene_name_of(b, tb);
    return std::tie(ua, ta, sa, a.date, a.git_commit, a.path) < std::tie(ub, tb, sb, b.date, b.git_commit, b.path);
  });
  return runs;
}

std::string dashboard_html(const std::vector<BenchRun>& runs, const nlohmann::ordered_json& paper,
                           const std::string& source, const std::vector<DashboardGenerator>& generators,
                           const std::vector<SweepRun>& sweeps, const std::vector<FrameRun>& frames) {
  std::map<std::string, std::string> series_colors;
  for (const auto& r : runs)
    for (const auto& [n, t] : r.tables)
      if (const std::string key = series_key(r, n); !series_colors.contains(key))
        series_colors[key] = series_color(series_colors.size());

  std::ostringstream os;
  os << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
     << "<title>vsgl-bench dashboard</title>\n<style>\n"
     << "body{font-family:sans-serif;margin:16px;color:#222;background:#fafafa}\n"
     << "h1{font-size:20px}h2{font-size:17px;margin-top:28px;border-bottom:1px solid #ccc}h3{font-size:14px}\n"
     << ".charts{display:flex;flex-wrap:wrap;gap:10px}\n"
     << "svg.chart{background:#fff;border:1px solid #ddd}\n"
     << "svg .title{font-size:13px;font-weight:bold}svg .tick,svg .bar-total,svg .x-label{font-size:10px}\n"
     << "svg .bar-label,svg .legend,svg .axis-label{font-size:10px}\n"
     << "svg .axis-title,svg .legend-label{font-size:11px}\n"
     << "table.runs,table.sweep-totals,table.fits,table.claims{border-collapse:collapse;font-size:12px;margin:6px 0}\n"
     << "table.runs td,table.runs th,table.sweep-totals td,table.sweep-totals th,table.fits td,table.fits th,"
        "table.claims td,table.claims th{border:1px solid #ccc;padding:2px 6px}\n"
     << "td.num,td.growth{white-space:nowrap}td.num{text-align:right}tr.flagged td{background:#fde0dc}tr.flagged "
        "strong{color:#a31515}\n"
     << "tr.claim.holds td{background:#e3f4e3}tr.claim.fails td{background:#fde0dc}p.note{font-size:12px;color:#555}\n"
     << ".incomplete{background:#fff1c2;color:#6b4e00;padding:1px 4px}\n"
     << "</style>\n</head>\n<body>\n";
  os << "<h1>vsgl-bench: VSGL generation timings (Tokuyoshi 2016, Tables 1 and 2)</h1>\n";
  os << "<p>" << runs.size() << " table runs and " << sweeps.size()
     << " sweep(s) (<a href=\"#scaling\">Scaling</a>) from <code>" << xml_escape(source)
     << "</code>; medians in ms. Each chart has its own scale: the paper's GTX 970 numbers are beside, not on, "
        "the measured ones. Hover a bar segment or a point for its numbers.</p>\n";

  // The sections in the runs' order: the paper's tables, then each other capture's scene.
  std::vector<Section> sections;
  for (const auto& r : runs)
    for (const auto& [n, t] : r.tables)
      if (const Section sec = section_of(r, n); std::find(sections.begin(), sections.end(), sec) == sections.end())
        sections.push_back(sec);
  for (const Section& section : sections) {
    const int table = section.table;
    std::vector<const BenchRun*> table_runs;
    for (const auto& r : runs)
      if (in_section(r, section)) table_runs.push_back(&r);
    std::vector<std::string> scenes;
    for (const BenchRun* r : table_runs)
      if (const std::string sc = scene_of(*r, table); std::find(scenes.begin(), scenes.end(), sc) == scenes.end())
        scenes.push_back(sc);
    std::string scene_list;
    for (const auto& sc : scenes) scene_list += (scene_list.empty() ? "" : "; ") + sc;
    os << "<section class=\"table\" id=\"" << section_id(section) << "\">\n<h2>";
    if (table != 0) os << "Table " << table << " (" << xml_escape(scene_list) << ")";
    else os << "Scene " << xml_escape(scene_list) << " (not a paper table: no paper numbers beside it)";
    os << "</h2>\n";
    os << "<h3>Phases per generator: camera view (dark) then light view (light), median ms</h3>\n<div class=\"charts\">\n";
    if (table != 0 && paper.contains("tables") && paper["tables"].contains(std::to_string(table)))
      os << paper_bars(paper, table, generators) << "\n";
    for (const BenchRun* r : table_runs) os << run_bars(*r, table, generators) << "\n";
    os << "</div>\n<h3>Totals across runs (date, commit), median with q1..q3, log axis</h3>\n<div class=\"charts\">\n";
    std::vector<std::string> timed;
    for (const BenchRun* r : table_runs)
      for (const RunSeries& s : r->series)
        if (s.is_total() && s.view.empty() && std::find(timed.begin(), timed.end(), s.generator) == timed.end())
          timed.push_back(s.generator);
    for (const auto& g : timed) os << total_series(table_runs, table, g, series_colors) << "\n";
    os << "</div>\n</section>\n";
  }

  os << scaling_section_html(sweeps, source);
  os << frame_section_html(frames, source);

  os << "<h2>Runs</h2>\n";
  if (runs.empty())
    os << "<p>No table JSON (the output of <code>tables</code>) under <code>" << xml_escape(source) << "</code>.</p>\n";
  os << "<table class=\"runs\"><tr><th>file</th><th>device</th><th>scene</th><th>started "
        "(UTC)</th><th>commit</th><th>notes</th></tr>\n";
  for (const auto& r : runs) {
    std::string notes = r.quick ? "--quick" : "";
    if (!r.altered_generators.empty()) notes += " " + altered_text(r);
    os << "<tr><td>" << xml_escape(r.path) << "</td><td>" << xml_escape(r.device) << "</td><td>"
       << xml_escape(scene_of(r, r.tables.begin()->first)) << "</td><td>" << xml_escape(r.date) << "</td><td>"
       << xml_escape(r.git_commit) << (r.git_dirty ? " (dirty)" : "") << "</td><td>" << xml_escape(notes)
       << "</td></tr>\n";
  }
  os << "</table>\n<p>Paper: " << xml_escape(paper.value("source", std::string("results/paper/paper_tables.json")))
     << ".</p>\n</body>\n</html>\n";
  return os.str();
}

}  // namespace vsgl
