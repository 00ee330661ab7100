#include "harness/sweep/sweep_report.hpp"

#include <algorithm>
#include <string>

#include "harness/compare/loglog_plot.hpp"
#include "harness/core/statistics.hpp"
#include "harness/core/text_format.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/sweep/sweep_expectations.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

ojson stats_json(const std::vector<double>& samples) {
  const SampleStats s = summarize(samples);
  return ojson{{"count", s.count}, {"median", s.median}, {"q1", s.q1},     {"q3", s.q3},
               {"min", s.min},     {"max", s.max},       {"mean", s.mean}, {"stdev", s.stdev}};
}

// A point's "values": each axis's name and value text.
ojson values_json(const std::vector<SweepAxis>& axes, const std::vector<std::size_t>& value_index) {
  ojson values = ojson::object();
  for (std::size_t a = 0; a < axes.size(); ++a) values[axes[a].name()] = axes[a].values[value_index[a]].text;
  return values;
}

ojson case_json(const CaseTiming& c) {
  ojson phases = ojson::array();
  for (std::size_t i = 0; i < c.phases.size(); ++i)
    phases.push_back(ojson{{"name", c.phases[i]}, {"stats", stats_json(c.phase_ms[i])}, {"samples_ms", c.phase_ms[i]}});
  return ojson{{"generator", c.generator},
               {"view", c.view},
               {"dispatches", c.dispatch_count},
               {"phases", phases},
               {"total", ojson{{"stats", stats_json(c.total_ms)}, {"samples_ms", c.total_ms}}}};
}

ojson slice_json(const SweepFit& f) {
  ojson j = ojson::object();
  for (const auto& [name, value] : f.slice) j[name] = value;
  return j;
}

std::string ms_text(double v) { return number_text(v, 4); }

// "1.234 (IQR 0.0123)": the median and its spread, as the tables print them.
std::string cell_text(const std::vector<double>& samples) {
  const SampleStats s = summarize(samples);
  return ms_text(s.median) + " (IQR " + ms_text(s.iqr()) + ")";
}

std::string verdict_text(const SweepFit& f) {
  if (!f.fit) return "no fit: " + f.note;
  if (!f.judgement) return "no expectation";
  const std::string v = growth_verdict_name(f.judgement->verdict);
  return f.judgement->flagged()
             ? "**" + v + "** (expected " + number_text(f.expected->slope, 3) + ": " + f.expected->why + ")"
             : v;
}

std::string file_part(std::string s) {
  for (char& c : s)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_')) c = '_';
  return s;
}

// Whether a fit's series was timed at the paper's setup in everything but the plotted axis (read
// off its first point's config: the view's size, N and K, and γ), so the paper's time belongs on it.
bool at_paper_setup(const MeasuredSweep& s, const SweepFit& f, const nlohmann::json& paper) {
  const SweepParameter plotted = s.axes[f.axis].parameter;
  const SweepPointResult& p = s.points[f.points.front()];
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
  return plotted == SweepParameter::kPdfSharpness || p.pdf_sharpness.value_or(1.0) == 1.0;
}

}  // namespace

std::optional<double> paper_reference_x(const nlohmann::json& paper, SweepParameter p, const std::string& view) {
  if (!parameter_touches_view(p, view) || !paper.is_object() || !paper.contains("setup")) return std::nullopt;
  const nlohmann::json& setup = paper.at("setup");
  const auto number = [&](const char* key) -> std::optional<double> {
    if (!setup.contains(key) || !setup.at(key).is_number()) return std::nullopt;
    return setup.at(key).get<double>();
  };
  const auto area = [&](const char* key) -> std::optional<double> {
    if (!setup.contains(key) || !setup.at(key).is_array() || setup.at(key).size() != 2) return std::nullopt;
    const nlohmann::json& wh = setup.at(key);
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

ojson sweep_json(const MeasuredSweep& s, const std::vector<SweepFit>& fits, const SweepContext& ctx,
                 const std::vector<PdfIndependence>& claims) {
  ojson axes = ojson::array();
  for (const SweepAxis& a : s.axes) {
    ojson values = ojson::array();
    for (const AxisValue& v : a.values) {
      ojson value{{"text", v.text}, {"value", v.value}, {"growth_x", growth_x(a.parameter, v)}};
      if (a.parameter == SweepParameter::kGbuffer) {
        value["width"] = v.width;
        value["height"] = v.height;
      }
      values.push_back(value);
    }
    axes.push_back(ojson{{"name", a.name()},
                         {"spec", a.spec},
                         {"symbol", growth_symbol(a.parameter)},
                         {"growth_x", growth_x_title(a.parameter)},
                         {"values", values}});
  }
  ojson points = ojson::array();
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const SweepPointResult& p = s.points[i];
    const ojson values = values_json(s.axes, p.value_index);
    ojson cases = ojson::array();
    for (const CaseTiming& c : p.timing.cases) cases.push_back(case_json(c));
    ojson point{{"index", i},
                {"values", values},
                {"capture_dir", p.capture_dir},
                {"capture", p.capture},
                {"config", p.config},
                {"timing", ojson{{"time_cap_s", p.time_cap_s},
                                 {"repetitions", p.timing.repetitions},
                                 {"timed_seconds", p.timing.timed_seconds},
                                 {"stop_reason", p.timing.stop_reason},
                                 {"worst_noise", p.timing.worst_noise}}},
                {"cases", cases}};
    if (p.pdf_sharpness) {
      ojson freq = ojson::object();
      for (const auto& [view, f] : p.pdf_frequency)
        freq[view] = ojson{{"relative_variance", f.relative_variance}, {"fine_share", f.fine_share}};
      point["pdf_sharpness"] =
          ojson{{"gamma", *p.pdf_sharpness},
                {"definition",
                 "both views' PDFs q raised to gamma, (q / max q)^gamma on the support (valid, q > 0), on a "
                 "copy of the capture before upload; pdf_frequency: the Haar spectrum of the result "
                 "(DESIGN.md §11a): relative_variance = var(p), fine_share[k] = share of mean(p^2) at "
                 "wavelengths below 2^(k+1) texels"},
                {"pdf_frequency", freq}};
    }
    points.push_back(point);
  }
  ojson beyond = ojson::array();
  for (const BeyondDevicePoint& b : s.beyond_device) {
    ojson entry{{"values", values_json(s.axes, b.value_index)}};
    if (!b.generator.empty()) entry["generator"] = b.generator;
    if (!b.view.empty()) entry["view"] = b.view;
    entry["reason"] = b.reason;
    beyond.push_back(entry);
  }
  ojson fit_list = ojson::array();
  for (const SweepFit& f : fits) {
    ojson j{{"axis", s.axes[f.axis].name()},
            {"slice", slice_json(f)},
            {"generator", f.generator},
            {"view", f.view},
            {"phase", f.phase},
            {"points", f.points},
            {"growth_x", f.x}};
    if (f.fit) {
      j["growth"] = ojson{{"slope", f.fit->slope},
                          {"low", f.fit->low},
                          {"high", f.fit->high},
                          {"confidence", f.fit->confidence},
                          {"resamples", f.fit->resamples},
                          {"points", f.fit->points},
                          {"text", growth_text(*f.fit, growth_symbol(s.axes[f.axis].parameter))}};
    } else {
      j["growth"] = nullptr;
      j["note"] = f.note;
    }
    if (f.expected)
      j["expected"] =
          ojson{{"slope", f.expected->slope}, {"tolerance", f.expected->tolerance}, {"why", f.expected->why}};
    else j["expected"] = nullptr;
    if (f.judgement) {
      j["verdict"] = growth_verdict_name(f.judgement->verdict);
      j["flagged"] = f.judgement->flagged();
      j["judgement"] = f.judgement->text;
    } else {
      j["verdict"] = nullptr;
      j["flagged"] = false;
    }
    fit_list.push_back(j);
  }
  ojson claim_list = ojson::array();
  const std::string text = ctx.paper.is_object() && ctx.paper.contains("claims") && ctx.paper["claims"].size() > 2
                               ? ctx.paper["claims"][2].get<std::string>()
                               : std::string("FIS cost is almost independent of the PDF, k-means cost is not");
  for (const PdfIndependence& c : claims) claim_list.push_back(to_json(c, text, ctx.informative));
  ojson budget = s.time_budget_s ? ojson(*s.time_budget_s) : ojson(nullptr);
  ojson doc{{"schema_version", kSweepSchemaVersion},
            {"kind", "sweep"},
            {"complete", s.complete},
            {"unit", "ms"},
            {"device", ctx.device},
            {"build", ctx.build},
            {"run", ctx.run},
            {"scene", to_json(s.scene)},
            {"generators", s.generators},
            {"axes", axes},
            {"time_budget_s", budget},
            {"time_budget_rule",
             "each point's time cap is the budget / the number of points; the minimum "
             "repetitions always run, so a point may exceed its cap"},
            {"fit_method",
             "least-squares slope of ln(median ms) over ln(growth_x) along one axis, the other axes "
             "held (a slice); percentile bootstrap over each point's rounds (DESIGN.md §9.1); judged "
             "against the expected slope ± tolerance"},
            {"points", points},
            {"beyond_device", beyond},
            {"fits", fit_list}};
  if (!claims.empty()) doc["claims"] = claim_list;
  return doc;
}

std::string sweep_markdown(const MeasuredSweep& s, const std::vector<SweepFit>& fits,
                           const std::vector<PdfIndependence>& claims) {
  std::string md = "# Sweep: " + scene_label(s.scene) + "\n\n";
  md += "Axes:";
  for (const SweepAxis& a : s.axes) md += " `" + a.spec + "`";
  md += " (" + std::to_string(s.points.size()) + " points). Median ms (IQR) per generator, view and phase";
  if (s.time_budget_s) md += "; time budget " + number_text(*s.time_budget_s, 4) + " s split over the points";
  md += ".\n";
  if (!s.beyond_device.empty()) {
    md += "\nBeyond this device, not timed (a case: its generator and view; else the whole point):\n\n";
    for (const BeyondDevicePoint& b : s.beyond_device)
      md += "- " + point_values_text(s.axes, b.value_index) +
            (b.generator.empty() ? std::string() : ", " + b.generator + " " + b.view) + ": " + b.reason + "\n";
  }
  std::size_t flagged = 0;
  for (const SweepFit& f : fits)
    if (f.judgement && f.judgement->flagged()) ++flagged;
  md += flagged == 0
            ? "No phase grows other than its algorithm predicts.\n"
            : std::to_string(flagged) + " fit(s) exclude the expected growth (marked **faster**/**slower**).\n";
  for (std::size_t a = 0; a < s.axes.size(); ++a) {
    const SweepAxis& axis = s.axes[a];
    md += "\n## Axis " + axis.name() + " (`" + axis.spec + "`)\n";
    std::string current_slice = "\x01";
    std::vector<std::size_t> columns;
    for (const SweepFit& f : fits) {
      if (f.axis != a) continue;
      const std::string st = slice_text(f.slice);
      if (st != current_slice) {
        current_slice = st;
        // The columns: every point any case of this slice was timed at (a case beyond the device
        // at one of them shows "beyond" there).
        columns.clear();
        for (const SweepFit& g : fits)
          if (g.axis == a && slice_text(g.slice) == st)
            for (std::size_t i : g.points)
              if (std::find(columns.begin(), columns.end(), i) == columns.end()) columns.push_back(i);
        std::sort(columns.begin(), columns.end(), [&](std::size_t i, std::size_t j) {
          return axis.values[s.points[i].value_index[a]].value < axis.values[s.points[j].value_index[a]].value;
        });
        if (!st.empty()) md += "\n### " + st + "\n";
        md += "\n| generator | view | phase |";
        for (std::size_t i : columns)
          md += " " + axis.name() + "=" + axis.values[s.points[i].value_index[a]].text + " |";
        md += " growth | verdict |\n|---|---|---|";
        for (std::size_t k = 0; k < columns.size(); ++k) md += "---:|";
        md += "---|---|\n";
      }
      md += "| " + f.generator + " | " + f.view + " | " + f.phase + " |";
      for (std::size_t i : columns) {
        const std::vector<double>* samples = find_point_samples(s.points[i], f.generator, f.view, f.phase);
        md += " " + (samples != nullptr ? cell_text(*samples) : std::string("beyond")) + " |";
      }
      md += " " + (f.fit ? growth_text(*f.fit, growth_symbol(axis.parameter)) : std::string("–")) + " | " +
            verdict_text(f) + " |\n";
    }
  }
  bool any_gamma = false;
  for (const SweepPointResult& p : s.points) any_gamma = any_gamma || p.pdf_sharpness.has_value();
  if (any_gamma) {
    md +=
        "\n## PDF frequency at each γ\n\nvar(p) of each view's PDF (DESIGN.md §11a), the measure FIS must not "
        "depend on.\n\n| point | γ | camera_view var(p) | light_view var(p) |\n|---:|---:|---:|---:|\n";
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const SweepPointResult& p = s.points[i];
      if (!p.pdf_sharpness) continue;
      const auto var = [&](const char* view) {
        const auto it = p.pdf_frequency.find(view);
        return it == p.pdf_frequency.end() ? std::string("–") : number_text(it->second.relative_variance, 4);
      };
      md += "| " + std::to_string(i) + " | " + number_text(*p.pdf_sharpness, 4) + " | " + var("camera_view") + " | " +
            var("light_view") + " |\n";
    }
  }
  for (const PdfIndependence& c : claims) {
    md += "\n## PDF independence" + (c.slice.empty() ? std::string() : " (" + slice_text(c.slice) + ")") + ": " +
          verdict_word(c.holds) + "\n\nChange of each view's median total from γ=" + number_text(c.reference_gamma, 4) +
          ", with 95 % bootstrap intervals; FIS must stay within ±" + number_text(100 * c.band, 3) +
          " % and each paper k-means generator must move more than either FIS.\n\n";
    md += "| generator | view |";
    for (const GammaChange& g : c.spreads.front().changes) md += " γ=" + number_text(g.gamma, 4) + " |";
    md += " spread |\n|---|---|";
    for (std::size_t k = 0; k < c.spreads.front().changes.size(); ++k) md += "---:|";
    md += "---:|\n";
    const auto pct = [](double v) { return number_text(100 * v, 3) + " %"; };
    for (const PdfSpread& p : c.spreads) {
      md += "| " + p.generator + " | " + p.view + " |";
      for (const GammaChange& g : p.changes) md += " " + pct(g.change) + " [" + pct(g.low) + ", " + pct(g.high) + "] |";
      md += " " + pct(p.spread) + " [" + pct(p.low) + ", " + pct(p.high) + "] |\n";
    }
    if (!c.note.empty()) md += "\n" + c.note + "\n";
  }
  return md;
}

std::vector<std::pair<std::string, std::string>> sweep_plots(const MeasuredSweep& s, const std::vector<SweepFit>& fits,
                                                             const nlohmann::json* paper) {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t a = 0; a < s.axes.size(); ++a) {
    std::vector<std::string> phases;
    for (const SweepFit& f : fits)
      if (f.axis == a && std::find(phases.begin(), phases.end(), f.phase) == phases.end()) phases.push_back(f.phase);
    for (const std::string& phase : phases) {
      std::vector<LogLogSeries> series;
      for (const SweepFit& f : fits) {
        if (f.axis != a || f.phase != phase) continue;
        LogLogSeries ser;
        ser.name = f.generator + " " + f.view + (f.slice.empty() ? "" : ", " + slice_text(f.slice));
        for (std::size_t k = 0; k < f.points.size(); ++k) {
          if (!(f.x[k] > 0)) continue;
          const SampleStats st = summarize(point_samples(s.points[f.points[k]], f.generator, f.view, f.phase));
          ser.points.push_back(LogLogPoint{f.x[k], st.median, st.q1, st.q3, {}});
        }
        if (paper != nullptr && s.paper_table > 0 && at_paper_setup(s, f, *paper))
          if (const auto x = paper_reference_x(*paper, s.axes[a].parameter, f.view)) {
            const std::string table = std::to_string(s.paper_table);
            const std::optional<double> ms = phase == "total"
                                                 ? paper_view_total(*paper, s.paper_table, f.generator, f.view)
                                                 : paper_number(*paper, {"tables", table, f.generator, f.view, phase});
            if (ms && *ms > 0) ser.references.push_back(LogLogReference{*x, *ms, "paper, Table " + table, {}});
          }
        if (!ser.points.empty()) series.push_back(std::move(ser));
      }
      if (series.empty()) continue;
      LogLogPlot plot;
      plot.title = phase + " over " + s.axes[a].name() + " (" + scene_label(s.scene) + ")";
      plot.x_title = growth_x_title(s.axes[a].parameter);
      out.emplace_back("sweep_" + file_part(s.axes[a].name()) + "_" + file_part(phase) + ".svg",
                       loglog_plot_svg(plot, series));
    }
  }
  return out;
}

}  // namespace vsgl
