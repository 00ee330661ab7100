#include "harness/sweep/sweep_plots.hpp"

#include <algorithm>
#include <stdexcept>

#include "harness/compare/loglog_plot.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/sweep/sweep_expectations.hpp"

namespace vsgl {
namespace {

std::string file_part(std::string s) {
  for (char& c : s)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_')) c = '_';
  return s;
}

// The parameter of an axis of the document (the reader keeps only names the schema lists).
SweepParameter parameter_of(const SweepAxisModel& axis) {
  const std::optional<SweepParameter> p = sweep_parameter_from_name(axis.name);
  if (!p) throw std::invalid_argument("sweep plots: unknown axis " + axis.name);
  return *p;
}

// Whether a fit's series was timed at the paper's setup in everything but the plotted axis (read
// off its first point's config: the view's size, N and K, and γ), so the paper's time belongs on it.
bool at_paper_setup(const SweepModel& s, const SweepFitModel& f, const nlohmann::ordered_json& paper) {
  const SweepParameter plotted = parameter_of(s.axes[f.axis]);
  const SweepPoint& p = s.points[f.points.front()];
  const auto& view = p.config.at("views").at(f.view);
  const double area = view.at("width").get<double>() * view.at("height").get<double>();
  const bool camera = f.view == "camera_view";
  const bool n_axis = plotted == SweepParameter::kVsgls || plotted == SweepParameter::kCameraVsgls ||
                      plotted == SweepParameter::kLightVsgls;
  const auto matches = [&](SweepParameter q, double value) {
    const std::optional<double> want = paper_reference_x(paper, q, f.view);
    return want && *want == value;
  };
  if (!n_axis && !matches(SweepParameter::kVsgls, view.at("vsgl_count").get<double>())) return false;
  const SweepParameter size = camera ? SweepParameter::kGbuffer : SweepParameter::kRsm;
  if (plotted != size && !matches(size, area)) return false;
  if (plotted != SweepParameter::kK && !matches(SweepParameter::kK, p.config.at("K").get<double>())) return false;
  return plotted == SweepParameter::kPdfSharpness || !p.pdf_sharpness || p.pdf_sharpness->gamma == 1.0;
}

// The paper's time of the fit's case and phase, where the series is at the paper's setup.
std::optional<LogLogReference> paper_mark(const SweepModel& s, const SweepFitModel& f,
                                          const nlohmann::ordered_json& paper, int paper_table) {
  if (paper_table <= 0 || !at_paper_setup(s, f, paper)) return std::nullopt;
  const std::optional<double> x = paper_reference_x(paper, parameter_of(s.axes[f.axis]), f.view);
  if (!x) return std::nullopt;
  const std::string table = std::to_string(paper_table);
  const std::optional<double> ms = f.phase == "total"
                                       ? paper_view_total(paper, paper_table, f.generator, f.view)
                                       : paper_number(paper, {"tables", table, f.generator, f.view, f.phase});
  if (!ms || !(*ms > 0)) return std::nullopt;
  return LogLogReference{*x, *ms, "paper, Table " + table, {}};
}

LogLogSeries fit_series(const SweepModel& s, const SweepFitModel& f, const nlohmann::ordered_json* paper,
                        int paper_table) {
  LogLogSeries ser;
  ser.name = f.generator + " " + f.view + (f.slice.empty() ? "" : ", " + sweep_slice_text(f.slice));
  for (std::size_t k = 0; k < f.points.size(); ++k) {
    if (!(f.growth_x[k] > 0)) continue;
    // read_sweep_model and sweep_document both give every point of a fit its case and phase.
    const TimingStatistics& st = *s.points[f.points[k]].find(f.generator, f.view)->find(f.phase);
    ser.points.push_back(LogLogPoint{f.growth_x[k], st.median_ms, st.q1_ms, st.q3_ms, {}});
  }
  if (paper != nullptr)
    if (const std::optional<LogLogReference> mark = paper_mark(s, f, *paper, paper_table))
      ser.references.push_back(*mark);
  return ser;
}

}  // namespace

std::optional<double> paper_reference_x(const nlohmann::ordered_json& paper, SweepParameter p,
                                        const std::string& view) {
  if (!parameter_touches_view(p, view) || !paper.is_object() || !paper.contains("setup")) return std::nullopt;
  const nlohmann::ordered_json& setup = paper.at("setup");
  const auto number = [&](const char* key) -> std::optional<double> {
    if (!setup.contains(key) || !setup.at(key).is_number()) return std::nullopt;
    return setup.at(key).get<double>();
  };
  const auto area = [&](const char* key) -> std::optional<double> {
    if (!setup.contains(key) || !setup.at(key).is_array() || setup.at(key).size() != 2) return std::nullopt;
    const nlohmann::ordered_json& wh = setup.at(key);
    if (!wh[0].is_number() || !wh[1].is_number()) return std::nullopt;
    return wh[0].get<double>() * wh[1].get<double>();
  };
  switch (p) {
    case SweepParameter::kVsgls:
    case SweepParameter::kCameraVsgls:
    case SweepParameter::kLightVsgls: return number(view == "camera_view" ? "vsgls_camera_view" : "vsgls_light_view");
    case SweepParameter::kK: return number("K");
    case SweepParameter::kGbuffer: return area("gbuffer");
    case SweepParameter::kRsm: return area("rsm");
    case SweepParameter::kPdfSharpness: return 1.0;
    case SweepParameter::kKmeansIterations: return std::nullopt;
  }
  return std::nullopt;
}

std::vector<std::pair<std::string, std::string>> sweep_plots(const SweepModel& s, const nlohmann::ordered_json* paper,
                                                             int paper_table) {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t a = 0; a < s.axes.size(); ++a) {
    std::vector<std::string> phases;
    for (const SweepFitModel& f : s.fits)
      if (f.axis == a && std::find(phases.begin(), phases.end(), f.phase) == phases.end()) phases.push_back(f.phase);
    for (const std::string& phase : phases) {
      std::vector<LogLogSeries> series;
      for (const SweepFitModel& f : s.fits) {
        if (f.axis != a || f.phase != phase) continue;
        LogLogSeries ser = fit_series(s, f, paper, paper_table);
        if (!ser.points.empty()) series.push_back(std::move(ser));
      }
      if (series.empty()) continue;
      LogLogPlot plot;
      plot.title = phase + " over " + s.axes[a].name + " (" + scene_label(s.scene) + ")";
      plot.x_title = s.axes[a].growth_x_title;
      out.emplace_back("sweep_" + file_part(s.axes[a].name) + "_" + file_part(phase) + ".svg",
                       loglog_plot_svg(plot, series));
    }
  }
  return out;
}

}  // namespace vsgl
