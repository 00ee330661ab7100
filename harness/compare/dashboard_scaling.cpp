#include "harness/compare/dashboard_scaling.hpp"

#include <algorithm>
#include <sstream>
#include <tuple>

#include "harness/compare/loglog_plot.hpp"
#include "harness/compare/svg_markup.hpp"
#include "harness/core/error.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/text_format.hpp"

namespace vsgl {
namespace {

std::string ms(double v) { return number_text(v, 4); }

std::string day(const std::string& date) { return date.substr(0, std::min<std::size_t>(date.size(), 10)); }

std::string short_commit(const SweepModel& m) {
  const std::string& commit = m.build.git_commit;
  if (commit.empty() || commit == "unknown") return "(no commit)";
  return commit.substr(0, std::min<std::size_t>(commit.size(), 7)) + (m.build.git_dirty ? " (dirty)" : "");
}

// "<generator> <view>" or, with other axes held, "<generator> <view>, K=2".
std::string series_name(const SweepFitModel& f) {
  const std::string slice = sweep_slice_text(f.slice);
  return f.generator + " " + f.view + (slice.empty() ? "" : ", " + slice);
}

const TimingStatistics& stats_at(const SweepModel& m, const SweepFitModel& f, std::size_t k) {
  // read_sweep_model checked that every point of a fit timed its case and phase.
  return *m.points[f.points[k]].find(f.generator, f.view)->find(f.phase);
}

std::vector<const SweepFitModel*> total_fits(const SweepModel& m, std::size_t axis) {
  std::vector<const SweepFitModel*> out;
  for (const SweepFitModel& f : m.fits)
    if (f.axis == axis && f.phase == "total") out.push_back(&f);
  return out;
}

// One series per generator, view and slice; the points off the log axis left out.
std::string totals_plot(const SweepModel& m, std::size_t axis) {
  const SweepAxisModel& a = m.axes[axis];
  std::vector<LogLogSeries> series;
  for (const SweepFitModel* f : total_fits(m, axis)) {
    LogLogSeries s;
    s.name = series_name(*f);
    for (std::size_t k = 0; k < f->points.size(); ++k) {
      if (!(f->growth_x[k] > 0)) continue;
      const TimingStatistics& st = stats_at(m, *f, k);
      const std::string value = a.values[m.points[f->points[k]].value_index[axis]].text;
      s.points.push_back(LogLogPoint{f->growth_x[k], st.median_ms, st.q1_ms, st.q3_ms,
                                     s.name + " at " + a.name + "=" + value + ": median " + ms(st.median_ms) +
                                         " ms (q1 " + ms(st.q1_ms) + ", q3 " + ms(st.q3_ms) + ", " +
                                         std::to_string(st.samples_ms.size()) + " rounds)"});
    }
    if (!s.points.empty()) series.push_back(std::move(s));
  }
  if (series.empty()) return "<p>No value of this axis sits on a log axis: nothing to plot.</p>\n";
  LogLogPlot plot;
  plot.title = "Total over " + a.name;  // the scene and device head the section
  plot.x_title = a.growth_x_title;
  plot.y_title = "ms: median, q1..q3";
  plot.width = 600;
  plot.plot_height = 260;
  return "<div class=\"charts\">\n" + loglog_plot_svg(plot, series) + "\n</div>\n";
}

// The totals at every value of the axis (γ = 0 too), median and quartiles.
std::string totals_table(const SweepModel& m, std::size_t axis) {
  const SweepAxisModel& a = m.axes[axis];
  const std::vector<const SweepFitModel*> fits = total_fits(m, axis);
  if (fits.empty()) return "";
  std::ostringstream os;
  os << "<table class=\"sweep-totals\"><tr><th>generator</th><th>view</th>";
  const bool sliced = m.axes.size() > 1;
  if (sliced) os << "<th>other axes</th>";
  bool off_axis = false;
  for (const SweepAxisValue& v : a.values) {
    os << "<th>" << xml_escape(a.name + "=" + v.text) << (v.growth_x > 0 ? "" : " *") << "</th>";
    off_axis = off_axis || !(v.growth_x > 0);
  }
  os << "</tr>\n";
  for (const SweepFitModel* f : fits) {
    os << "<tr><td>" << xml_escape(f->generator) << "</td><td>" << xml_escape(f->view) << "</td>";
    if (sliced) os << "<td>" << xml_escape(sweep_slice_text(f->slice)) << "</td>";
    for (std::size_t v = 0; v < a.values.size(); ++v) {
      std::string cell = "–";
      for (std::size_t k = 0; k < f->points.size(); ++k)
        if (m.points[f->points[k]].value_index[axis] == v) {
          const TimingStatistics& st = stats_at(m, *f, k);
          cell = ms(st.median_ms) + " (" + ms(st.q1_ms) + "–" + ms(st.q3_ms) + ")";
        }
      os << "<td class=\"num\">" << xml_escape(cell) << "</td>";
    }
    os << "</tr>\n";
  }
  os << "</table>\n";
  if (off_axis)
    os << "<p class=\"note\">* growth x 0 (γ = 0): timed and listed, left off the log axis and the fits.</p>\n";
  return os.str();
}

std::string expected_text(const SweepFitModel& f) {
  if (!f.expected) return "none";
  return number_text(f.expected->slope, 3) + " ± " + number_text(f.expected->tolerance, 3) + ": " + f.expected->why;
}

// Every fit along the axis, totals and phases; a flagged one highlighted.
std::string fits_table(const SweepModel& m, std::size_t axis) {
  std::ostringstream os;
  const bool sliced = m.axes.size() > 1;
  os << "<table class=\"fits\"><tr>" << (sliced ? "<th>other axes</th>" : "")
     << "<th>generator</th><th>view</th><th>phase</th><th>growth</th><th>expected</th><th>verdict</th></tr>\n";
  for (const SweepFitModel& f : m.fits) {
    if (f.axis != axis) continue;
    os << (f.flagged() ? "<tr class=\"flagged\">" : "<tr>");
    if (sliced) os << "<td>" << xml_escape(sweep_slice_text(f.slice)) << "</td>";
    os << "<td>" << xml_escape(f.generator) << "</td><td>" << xml_escape(f.view) << "</td><td>" << xml_escape(f.phase)
       << "</td><td class=\"growth\">" << xml_escape(f.growth ? f.growth->text : "no fit: " + f.note) << "</td><td>"
       << xml_escape(expected_text(f)) << "</td><td";
    if (!f.judgement.empty()) os << " title=\"" << xml_escape(f.judgement) << "\"";
    os << ">";
    const std::string verdict = f.verdict ? f.verdict_word() : "no expectation";
    if (f.flagged()) os << "<strong>" << xml_escape(verdict) << "</strong>";
    else os << xml_escape(verdict);
    os << "</td></tr>\n";
  }
  os << "</table>\n";
  return os.str();
}

std::string claims_table(const SweepModel& m) {
  if (!m.claims || m.claims->empty()) return "";
  std::ostringstream os;
  os << "<h4>The paper's claims judged on this sweep</h4>\n<table class=\"claims\"><tr><th>claim</th><th>statement</th>"
        "<th>other axes</th><th>result</th><th>note</th></tr>\n";
  for (const SweepClaim& s : *m.claims) {
    const Claim& c = s.claim;
    const std::string result = claim_verdict(c);
    const char* css = !c.verdict || c.verdict->inconclusive() ? "inconclusive" : c.verdict->holds() ? "holds" : "fails";
    os << "<tr class=\"claim " << css << "\"><td>" << xml_escape(c.id) << "</td><td title=\""
       << xml_escape("criterion: " + c.criterion) << "\">" << xml_escape(c.text) << "</td><td>"
       << xml_escape(s.slice.empty() ? "–" : sweep_slice_text(s.slice)) << "</td><td>" << result
       << (c.informative ? " (informative only: not a GPU's timing)" : "") << "</td><td>" << xml_escape(claim_note(c))
       << "</td></tr>\n";
  }
  os << "</table>\n";
  return os.str();
}

// The heading's mark of a sweep.json written while its run went on (DESIGN.md §10.1); "" when complete.
std::string incomplete_mark(const SweepModel& m) {
  if (m.complete) return "";
  return " <span class=\"incomplete\">incomplete: " + std::to_string(m.reached_points()) + " of " +
         std::to_string(m.planned_points()) + " points</span>";
}

std::string sweep_block(const SweepRun& run, std::size_t number) {
  const SweepModel& m = run.model;
  std::size_t flagged = 0;
  for (const SweepFitModel& f : m.fits) flagged += f.flagged() ? 1 : 0;
  std::string axes;
  for (const SweepAxisModel& a : m.axes) axes += (axes.empty() ? "" : " × ") + a.spec;
  std::string generators;
  for (const std::string& g : m.generators) generators += (generators.empty() ? "" : ", ") + g;

  std::ostringstream os;
  os << "<section class=\"sweep\" id=\"sweep" << number << "\">\n<h3>" << xml_escape(scene_label(m.scene)) << ": "
     << xml_escape(m.device.name) << ", " << xml_escape(day(m.run.started_utc)) << ", commit "
     << xml_escape(short_commit(m)) << (m.run.quick ? " (quick)" : "") << incomplete_mark(m) << "</h3>\n";
  if (!m.complete)
    os << "<p class=\"incomplete\">This sweep did not finish: its run stopped, or is still running, after "
       << m.reached_points() << " of " << m.planned_points()
       << " points. The fits are over the points timed so far; the paper's claims are judged only on a complete "
          "sweep.</p>\n";
  os << "<p><code>" << xml_escape(run.path) << "</code>: " << xml_escape(axes) << " (" << m.points.size()
     << " points), " << xml_escape(generators) << ", started " << xml_escape(m.run.started_utc) << ". "
     << (flagged == 0 ? std::string("No fit excludes the growth its algorithm predicts.")
                      : std::to_string(flagged) + " fit(s) exclude the growth their algorithm predicts (highlighted).")
     << "</p>\n";
  if (!m.beyond_device.empty()) {
    os << "<p class=\"beyond\">Beyond this device, not timed:</p>\n<ul class=\"beyond\">\n";
    for (const SweepBeyondDevice& b : m.beyond_device) {
      std::string values;
      for (std::size_t a = 0; a < m.axes.size(); ++a)
        values += (values.empty() ? "" : ", ") + m.axes[a].name + "=" + m.axes[a].values[b.value_index[a]].text;
      if (!b.generator.empty()) values += ", " + b.generator + " " + b.view;
      os << "<li>" << xml_escape(values) << ": " << xml_escape(b.reason) << "</li>\n";
    }
    os << "</ul>\n";
  }
  for (std::size_t a = 0; a < m.axes.size(); ++a) {
    os << "<div class=\"axis\" data-axis=\"" << xml_escape(m.axes[a].name) << "\">\n<h4>Axis "
       << xml_escape(m.axes[a].name) << " (<code>" << xml_escape(m.axes[a].spec) << "</code>)</h4>\n";
    os << totals_plot(m, a) << totals_table(m, a) << fits_table(m, a) << "</div>\n";
  }
  os << claims_table(m) << "</section>\n";
  return os.str();
}

}  // namespace

std::vector<SweepRun> find_sweep_runs(const std::filesystem::path& results_dir) {
  if (!std::filesystem::is_directory(results_dir)) throw InputError(path_text(results_dir) + ": not a directory");
  std::vector<SweepRun> runs;
  for (const auto& e : std::filesystem::recursive_directory_iterator(results_dir)) {
    if (!e.is_regular_file() || e.path().filename() != "sweep.json") continue;
    runs.push_back(
        SweepRun{std::filesystem::relative(e.path(), results_dir).generic_string(), read_sweep_file(e.path())});
  }
  std::sort(runs.begin(), runs.end(), [](const SweepRun& a, const SweepRun& b) {
    const std::string sa = scene_label(a.model.scene), sb = scene_label(b.model.scene);
    const std::string da = a.model.run.started_utc, db = b.model.run.started_utc;
    return std::tie(sa, da, a.path) < std::tie(sb, db, b.path);
  });
  return runs;
}

std::string scaling_section_html(const std::vector<SweepRun>& sweeps, const std::string& source) {
  std::ostringstream os;
  os << "<section class=\"scaling\" id=\"scaling\">\n<h2>Scaling</h2>\n";
  if (sweeps.empty()) {
    os << "<p class=\"no-sweep\">No sweep JSON (<code>sweep.json</code> of <code>vsgl-bench sweep</code>) under <code>"
       << xml_escape(source) << "</code>.</p>\n</section>\n";
    return os.str();
  }
  os << "<p>" << sweeps.size()
     << " sweep(s): how each generator's cost grows along each axis, the other axes held (DESIGN.md §10.1). "
        "Growth is the log-log slope with its bootstrap interval, judged against what the algorithm predicts.</p>\n";
  for (std::size_t i = 0; i < sweeps.size(); ++i) os << sweep_block(sweeps[i], i + 1);
  os << "</section>\n";
  return os.str();
}

}  // namespace vsgl
