#include "harness/formats/quality_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "harness/core/json_reader.hpp"
#include "harness/core/sorted_json.hpp"
#include "harness/core/statistics.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;

CoverageCountsSummary read_counts(const JsonReader& r, const json& o, const std::string& p) {
  return {r.number(o, p, "gap"), r.number(o, p, "surplus"), r.number(o, p, "count_error"), r.number(o, p, "mean_count"),
          r.optional_number(o, p, "overlap")};
}

CoverageSummary read_coverage(const JsonReader& r, const json& c, const std::string& p) {
  CoverageSummary s;
  s.gap = r.number(c, p, "gap");
  s.overlap = r.number(c, p, "overlap");
  s.gap_plus_overlap = r.number(c, p, "gap_plus_overlap");
  s.texels_with_pdf = r.uint64(c, p, "texels_with_pdf");
  s.gap_texels = r.uint64(c, p, "gap_texels");
  s.overlap_texels = r.uint64(c, p, "overlap_texels");
  const json& m = r.object(c, p, "mass_over_target");
  const std::string mp = p + "/mass_over_target";
  s.mass_over_target = {r.number(m, mp, "mean"), r.number(m, mp, "stdev"), r.number(m, mp, "min"),
                        r.number(m, mp, "max"), r.number(m, mp, "p99")};
  s.box = read_counts(r, r.object(c, p, "box"), p + "/box");
  s.eq3 = read_counts(r, r.object(c, p, "eq3"), p + "/eq3");
  const json& floor = r.object(c, p, "lattice_floor");
  s.floor_box = read_counts(r, r.object(floor, p + "/lattice_floor", "box"), p + "/lattice_floor/box");
  s.floor_eq3 = read_counts(r, r.object(floor, p + "/lattice_floor", "eq3"), p + "/lattice_floor/eq3");
  const json& excess = r.object(c, p, "excess");
  s.excess_box = read_counts(r, r.object(excess, p + "/excess", "box"), p + "/excess/box");
  s.excess_eq3 = read_counts(r, r.object(excess, p + "/excess", "eq3"), p + "/excess/eq3");
  return s;
}

PowerSummary read_power(const JsonReader& r, const json& o, const std::string& p) {
  return {r.number(o, p, "max_over_mean"), r.number(o, p, "p99_over_mean"), r.number(o, p, "power_ratio"),
          r.number(o, p, "sum_vsgl_power"), r.number(o, p, "total_flux")};
}

ImageErrorSummary read_error(const JsonReader& r, const json& o, const std::string& p) {
  return {r.number(o, p, "relative_rmse"), r.number(o, p, "p99_pixel_error")};
}

ViewQuality read_view(const JsonReader& r, const json& v, const std::string& p) {
  ViewQuality out;
  out.vsgls = r.member(v, p, "vsgls");
  out.total_flux = r.number(v, p, "total_flux");
  if (v.contains("pdf_frequency")) {
    const json& f = r.object(v, p, "pdf_frequency");
    const std::string fp = p + "/pdf_frequency";
    PdfFrequencySummary s;
    s.relative_variance = r.number(f, fp, "relative_variance");
    s.fine_share = r.numbers(f, fp, "fine_share");
    s.detail_energy = r.numbers(f, fp, "detail_energy");
    s.mean_square = r.number(f, fp, "mean_square");
    s.share_below_8_texels = r.number(f, fp, "share_below_8_texels");
    s.definition = r.string(f, fp, "definition");
    s.share_below_kernel = r.number(f, fp, "share_below_kernel");
    s.share_below_kernel_side_texels = r.number(f, fp, "share_below_kernel_side_texels");
    s.mean_kernel_side_texels = r.number(f, fp, "mean_kernel_side_texels");
    out.pdf_frequency = s;
  }
  if (v.contains("flux_by_pdf")) {
    const json& f = r.object(v, p, "flux_by_pdf");
    const std::string fp = p + "/flux_by_pdf";
    FluxByPdfSummary s;
    s.bounds = r.numbers(f, fp, "bounds");
    for (double t : r.numbers(f, fp, "texels")) s.texels.push_back(static_cast<uint64_t>(t));
    s.flux_share = r.numbers(f, fp, "flux_share");
    s.oversized_mass = r.number(f, fp, "oversized_mass");
    s.definition = r.string(f, fp, "definition");
    out.flux_by_pdf = s;
  }
  for (const auto& [name, g] : r.object(v, p, "generators").items()) {
    const std::string gp = p + "/generators/" + name;
    if (!g.is_object()) r.wrong_type(g, gp, "an object");
    GeneratorQuality q;
    if (g.contains("coverage")) q.coverage = read_coverage(r, r.object(g, gp, "coverage"), gp + "/coverage");
    q.power = read_power(r, r.object(g, gp, "power"), gp + "/power");
    if (g.contains("flux_origin")) {
      const json& f = r.object(g, gp, "flux_origin");
      const std::string fp = gp + "/flux_origin";
      q.flux_origin = FluxOriginSummary{r.numbers(f, fp, "gathered"),
                                        r.numbers(f, fp, "gathered_by_oversized"),
                                        r.number(f, fp, "attributed_power_ratio"),
                                        r.number(f, fp, "pdf_weighted_count"),
                                        r.number(f, fp, "oversized_kernels"),
                                        std::nullopt};
      if (f.contains("over_frames")) {
        const json& o = r.object(f, fp, "over_frames");
        const std::string op = fp + "/over_frames";
        q.flux_origin->over_frames = FluxOriginFrames{
            r.uint32(o, op, "frames"),     r.numbers(o, op, "gathered_mean"),      r.numbers(o, op, "gathered_stdev"),
            r.number(o, op, "ratio_mean"), r.number(o, op, "ratio_stdev"),         r.number(o, op, "ratio_min"),
            r.number(o, op, "ratio_max"),  r.number(o, op, "oversized_share_mean")};
      }
    }
    out.generators[name] = q;
  }
  return out;
}

json counts_json(const CoverageCountsSummary& c) {
  json j{{"gap", c.gap}, {"surplus", c.surplus}, {"count_error", c.count_error}, {"mean_count", c.mean_count}};
  if (c.overlap) j["overlap"] = *c.overlap;
  return j;
}

json coverage_json(const CoverageSummary& s) {
  const MassSummary& m = s.mass_over_target;
  return json{
      {"gap", s.gap},
      {"overlap", s.overlap},
      {"gap_plus_overlap", s.gap_plus_overlap},
      {"texels_with_pdf", s.texels_with_pdf},
      {"gap_texels", s.gap_texels},
      {"overlap_texels", s.overlap_texels},
      {"mass_over_target", json{{"mean", m.mean}, {"stdev", m.stdev}, {"min", m.min}, {"max", m.max}, {"p99", m.p99}}},
      {"box", counts_json(s.box)},
      {"eq3", counts_json(s.eq3)},
      {"lattice_floor", json{{"box", counts_json(s.floor_box)}, {"eq3", counts_json(s.floor_eq3)}}},
      {"excess", json{{"box", counts_json(s.excess_box)}, {"eq3", counts_json(s.excess_eq3)}}}};
}

json power_json(const PowerSummary& p) {
  return json{{"sum_vsgl_power", p.sum_vsgl_power},
              {"total_flux", p.total_flux},
              {"power_ratio", p.power_ratio},
              {"max_over_mean", p.max_over_mean},
              {"p99_over_mean", p.p99_over_mean}};
}

json error_json(const ImageErrorSummary& e) {
  return json{{"relative_rmse", e.relative_rmse}, {"p99_pixel_error", e.p99_pixel_error}};
}

// A frame series with its summary (DESIGN.md §11a.1); only per_frame is read back, the rest derives from it.
json series_json(const FrameSeries& series) {
  json out = json::object();
  for (const auto& [name, values] : series) {
    const SampleStats sum = summarize(values);
    out[name] = json{{"per_frame", values}, {"mean", sum.mean}, {"p95", sum.p95}, {"max", sum.max}};
  }
  return out;
}

FrameSeries read_series(const JsonReader& r, const json& o, const std::string& p) {
  FrameSeries series;
  for (const auto& [name, v] : o.items()) {
    const std::string mp = p + "/" + name;
    if (!v.is_object()) r.wrong_type(v, mp, "an object");
    series[name] = r.numbers(v, mp, "per_frame");
    if (series[name].size() < 2)
      r.fail(mp + "/per_frame", "has " + std::to_string(series[name].size()) + " frame(s); a series needs at least 2");
  }
  return series;
}

// Series against several rungs (schema 7), coarsest first.
json series_list_json(const std::vector<FrameSeries>& list) {
  json out = json::array();
  for (const FrameSeries& s : list) out.push_back(series_json(s));
  return out;
}

std::vector<FrameSeries> read_series_list(const JsonReader& r, const json& o, const std::string& p,
                                          std::string_view key) {
  std::vector<FrameSeries> list;
  const std::string lp = r.child(p, key);
  for (std::size_t i = 0; const json& s : r.array(o, p, key)) {
    const std::string sp = r.element(lp, i++);
    if (!s.is_object()) r.wrong_type(s, sp, "an object");
    list.push_back(read_series(r, s, sp));
  }
  return list;
}

// A generator's worst frame: the one of largest relative RMSE.
json frame_errors_json(const FrameErrors& f) {
  json gens = json::object();
  for (const auto& [name, series] : f.generators) {
    json g{{"series", series_json(series)}};
    if (const auto it = series.find("relative_rmse"); it != series.end())
      g["worst_frame"] = std::max_element(it->second.begin(), it->second.end()) - it->second.begin();
    if (const auto it = f.second_rung.find(name); it != f.second_rung.end()) g["second_rung"] = series_json(it->second);
    if (const auto it = f.coarse_rungs.find(name); it != f.coarse_rungs.end())
      g["coarse_rungs"] = series_list_json(it->second);
    gens[name] = g;
  }
  json out{{"gbuffer_stride", f.gbuffer_stride}, {"image", f.image}, {"reference", f.reference}, {"generators", gens}};
  // FLIP's settings where the series hold FLIP (not the occlusion's, DESIGN.md §11a.2).
  if (f.flip_pixels_per_degree > 0)
    out["flip"] = json{{"exposure", f.flip_exposure}, {"pixels_per_degree", f.flip_pixels_per_degree}};
  if (!f.second_rung_reference.empty()) out["second_rung_reference"] = f.second_rung_reference;
  if (!f.coarse_rung_strides.empty()) out["coarse_rung_strides"] = f.coarse_rung_strides;
  return out;
}

FrameErrors read_frame_errors(const JsonReader& r, const json& o, const std::string& p) {
  FrameErrors f;
  f.gbuffer_stride = r.uint32(o, p, "gbuffer_stride");
  f.image = r.array(o, p, "image", 2);
  f.reference = r.string(o, p, "reference");
  if (const json* flip = r.optional_object(o, p, "flip")) {
    f.flip_exposure = r.number(*flip, p + "/flip", "exposure");
    f.flip_pixels_per_degree = r.number(*flip, p + "/flip", "pixels_per_degree");
  }
  for (const auto& [g, v] : r.object(o, p, "generators").items()) {
    const std::string gp = p + "/generators/" + g;
    if (!v.is_object()) r.wrong_type(v, gp, "an object");
    f.generators[g] = read_series(r, r.object(v, gp, "series"), gp + "/series");
    if (const json* second = r.optional_object(v, gp, "second_rung"))
      f.second_rung[g] = read_series(r, *second, gp + "/second_rung");
    if (v.contains("coarse_rungs")) f.coarse_rungs[g] = read_series_list(r, v, gp, "coarse_rungs");
  }
  f.second_rung_reference = r.optional_string(o, p, "second_rung_reference").value_or("");
  if (o.contains("coarse_rung_strides"))
    for (std::size_t i = 0; const json& s : r.array(o, p, "coarse_rung_strides"))
      f.coarse_rung_strides.push_back(static_cast<uint32_t>(r.uint64(s, r.element(p + "/coarse_rung_strides", i++))));
  for (const auto& [g, rungs] : f.coarse_rungs)
    if (rungs.size() != f.coarse_rung_strides.size())
      r.fail(p + "/generators/" + g + "/coarse_rungs", "has " + std::to_string(rungs.size()) + " rung(s), but " +
                                                           std::to_string(f.coarse_rung_strides.size()) +
                                                           " coarse_rung_strides");
  return f;
}

// A ladder value that may be infinite or NaN (DESIGN.md §11a): JSON has no such number, so null.
json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

double number_or(const JsonReader& r, const json& v, const std::string& p, double if_null) {
  return v.is_null() ? if_null : r.number(v, p);
}

json ladder_json(const ReferenceLadder& l) {
  json metrics = json::object();
  for (const auto& [name, m] : l.metrics) {
    json ratios = json::array();
    for (double x : m.ratios) ratios.push_back(finite_or_null(x));
    metrics[name] = json{{"differences", m.differences},
                         {"ratios", ratios},
                         {"rate", finite_or_null(m.rate)},
                         {"remaining_error", finite_or_null(m.remaining)}};
  }
  json out{{"rsm_strides", l.rsm_strides}, {"rsm_sides", l.rsm_sides}};
  if (!l.mean_luminances.empty()) out["mean_luminance"] = l.mean_luminances;
  out["metrics"] = metrics;
  out["note"] = l.note;
  return out;
}

ReferenceLadder read_ladder(const JsonReader& r, const json& o, const std::string& p) {
  ReferenceLadder l;
  const auto uints = [&](const char* key) {
    std::vector<uint32_t> out;
    const json& a = r.array(o, p, key);
    for (std::size_t i = 0; i < a.size(); ++i)
      out.push_back(static_cast<uint32_t>(r.uint64(a[i], r.element(r.child(p, key), i))));
    return out;
  };
  l.rsm_strides = uints("rsm_strides");
  l.rsm_sides = uints("rsm_sides");
  if (l.rsm_sides.size() != l.rsm_strides.size())
    r.fail(r.child(p, "rsm_sides"),
           "has " + std::to_string(l.rsm_sides.size()) + " rungs, rsm_strides " + std::to_string(l.rsm_strides.size()));
  if (o.contains("mean_luminance")) {
    l.mean_luminances = r.numbers(o, p, "mean_luminance");
    if (l.mean_luminances.size() != l.rsm_strides.size())
      r.fail(r.child(p, "mean_luminance"), "has " + std::to_string(l.mean_luminances.size()) + " rungs, rsm_strides " +
                                               std::to_string(l.rsm_strides.size()));
  }
  l.note = r.string(o, p, "note");
  for (const auto& [name, v] : r.object(o, p, "metrics").items()) {
    const std::string mp = p + "/metrics/" + name;
    if (!v.is_object()) r.wrong_type(v, mp, "an object");
    ReferenceLadderMetric m;
    m.differences = r.numbers(v, mp, "differences");
    const json& ratios = r.array(v, mp, "ratios");
    for (std::size_t i = 0; i < ratios.size(); ++i)
      m.ratios.push_back(
          number_or(r, ratios[i], r.element(mp + "/ratios", i), std::numeric_limits<double>::quiet_NaN()));
    m.rate = number_or(r, r.member(v, mp, "rate"), mp + "/rate", std::numeric_limits<double>::quiet_NaN());
    m.remaining = number_or(r, r.member(v, mp, "remaining_error"), mp + "/remaining_error",
                            std::numeric_limits<double>::infinity());
    l.metrics[name] = std::move(m);
  }
  return l;
}

json reference_detail_json(const ReferenceDetail& d) {
  json rows = json::array();
  for (const ReferenceConvergenceRow& r : d.convergence)
    rows.push_back(json{
        {"rsm_stride", r.rsm_stride}, {"vpls", r.vpls}, {"relative_rmse", r.relative_rmse}, {"seconds", r.seconds}});
  json size{{"error_stride", d.error_stride}, {"rule", d.camera_size_rule}, {"budget_s", d.budget_s}};
  if (d.predicted_full_size_s) size["predicted_full_size_s"] = *d.predicted_full_size_s;
  json out{{"convergence", rows},
           {"own_error", d.own_error},
           {"seconds", d.seconds},
           {"support", json{{"vpls", d.support_vpls},
                            {"power_ratio", d.support_power_ratio},
                            {"seconds", d.support_seconds},
                            {"relative_rmse_to_all_lit", d.support_vs_all_lit}}},
           {"camera_size", size},
           {"dispatch", json{{"evaluations_per_dispatch", d.evaluations_per_dispatch},
                             {"vsgls_per_dispatch", d.vsgls_per_dispatch}}}};
  if (!d.own_errors.empty()) out["own_errors"] = d.own_errors;
  if (d.ladder) out["ladder"] = ladder_json(*d.ladder);
  return out;
}

// `ladder_required`: a schema-6 document, whose reference-decided claims are judged by its ladder.
ReferenceDetail read_reference_detail(const JsonReader& r, const json& ref, bool ladder_required) {
  ReferenceDetail d;
  const json& rows = r.array(ref, "/reference", "convergence");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string p = r.element("/reference/convergence", i);
    if (!rows[i].is_object()) r.wrong_type(rows[i], p, "an object");
    d.convergence.push_back({r.uint32(rows[i], p, "rsm_stride"), r.uint64(rows[i], p, "vpls"),
                             r.number(rows[i], p, "relative_rmse"), r.number(rows[i], p, "seconds")});
  }
  d.own_error = r.number(ref, "/reference", "own_error");
  if (const json* own = r.optional_object(ref, "/reference", "own_errors"))
    for (const auto& [metric, v] : own->items()) d.own_errors[metric] = r.number(v, "/reference/own_errors/" + metric);
  d.seconds = r.number(ref, "/reference", "seconds");
  const json& sup = r.object(ref, "/reference", "support");
  d.support_vpls = r.uint64(sup, "/reference/support", "vpls");
  d.support_power_ratio = r.number(sup, "/reference/support", "power_ratio");
  d.support_seconds = r.number(sup, "/reference/support", "seconds");
  d.support_vs_all_lit = r.number(sup, "/reference/support", "relative_rmse_to_all_lit");
  const json& size = r.object(ref, "/reference", "camera_size");
  d.error_stride = r.uint32(size, "/reference/camera_size", "error_stride");
  d.camera_size_rule = r.string(size, "/reference/camera_size", "rule");
  d.budget_s = r.number(size, "/reference/camera_size", "budget_s");
  d.predicted_full_size_s = r.optional_number(size, "/reference/camera_size", "predicted_full_size_s");
  const json& disp = r.object(ref, "/reference", "dispatch");
  d.evaluations_per_dispatch = r.uint64(disp, "/reference/dispatch", "evaluations_per_dispatch");
  d.vsgls_per_dispatch = r.uint32(disp, "/reference/dispatch", "vsgls_per_dispatch");
  if (ladder_required || ref.contains("ladder"))
    d.ladder = read_ladder(r, r.object(ref, "/reference", "ladder"), "/reference/ladder");
  return d;
}

json view_json(const ViewQuality& v) {
  json j{{"vsgls", v.vsgls}, {"total_flux", v.total_flux}, {"generators", json::object()}};
  if (v.pdf_frequency) {
    const PdfFrequencySummary& f = *v.pdf_frequency;
    j["pdf_frequency"] = json{{"detail_energy", f.detail_energy},
                              {"fine_share", f.fine_share},
                              {"mean_square", f.mean_square},
                              {"relative_variance", f.relative_variance},
                              {"share_below_8_texels", f.share_below_8_texels},
                              {"mean_kernel_side_texels", f.mean_kernel_side_texels},
                              {"share_below_kernel_side_texels", f.share_below_kernel_side_texels},
                              {"share_below_kernel", f.share_below_kernel},
                              {"definition", f.definition}};
  }
  if (v.flux_by_pdf) {
    const FluxByPdfSummary& f = *v.flux_by_pdf;
    j["flux_by_pdf"] = json{{"bounds", f.bounds},
                            {"texels", f.texels},
                            {"flux_share", f.flux_share},
                            {"oversized_mass", f.oversized_mass},
                            {"definition", f.definition}};
  }
  for (const auto& [name, g] : v.generators) {
    json gj{{"power", power_json(g.power)}};
    if (g.coverage) gj["coverage"] = coverage_json(*g.coverage);
    if (g.flux_origin) {
      const FluxOriginSummary& f = *g.flux_origin;
      gj["flux_origin"] = json{{"gathered", f.gathered},
                               {"gathered_by_oversized", f.gathered_by_oversized},
                               {"attributed_power_ratio", f.attributed_power_ratio},
                               {"pdf_weighted_count", f.pdf_weighted_count},
                               {"oversized_kernels", f.oversized_kernels}};
      if (f.over_frames) {
        const FluxOriginFrames& o = *f.over_frames;
        gj["flux_origin"]["over_frames"] = json{{"frames", o.frames},
                                                {"gathered_mean", o.gathered_mean},
                                                {"gathered_stdev", o.gathered_stdev},
                                                {"ratio_mean", o.ratio_mean},
                                                {"ratio_stdev", o.ratio_stdev},
                                                {"ratio_min", o.ratio_min},
                                                {"ratio_max", o.ratio_max},
                                                {"oversized_share_mean", o.oversized_share_mean}};
      }
    }
    j["generators"][name] = gj;
  }
  return j;
}

json animated_json(const QualityModel::Animated& a) {
  json gens = json::object();
  for (const auto& [name, f] : a.generators)
    gens[name] = json{
        {"weighted_cv", f.weighted_cv}, {"error_cv", f.error_cv}, {"power_relative_stdev", f.power_relative_stdev}};
  return json{{"sequence", a.sequence},
              {"scene", a.scene},
              {"frames", a.frames},
              {"frame_content_hashes", a.frame_content_hashes},
              {"gbuffer_stride", a.gbuffer_stride},
              {"reference_rsm_stride", a.reference_rsm_stride},
              {"reference_weighted_cv", a.reference_weighted_cv},
              {"note", a.note},
              {"generators", gens}};
}

json occlusion_json(const OcclusionMeasure& o) {
  json control = json::object();
  for (const auto& [name, values] : o.control) control[name] = values;
  return json{{"visibility", o.visibility},
              {"reference", json{{"rsm_stride", o.reference_rsm_stride},
                                 {"rsm_side", o.reference_rsm_side},
                                 {"vpls", o.reference_vpls},
                                 {"seconds", o.reference_seconds},
                                 {"ladder", ladder_json(o.ladder)}}},
              {"region", json{{"rule", o.region_rule},
                              {"surface_pixels", o.surface_pixels},
                              {"occluded_pixels", o.occluded_pixels},
                              {"unshadowed_mean_luminance", o.unshadowed_mean_luminance},
                              {"occluded_light_share", o.occluded_light_share}}},
              {"note", o.note},
              {"frames", frame_errors_json(o.frames)},
              {"control", json{{"frames", o.control_frames}, {"relative_rmse", control}}}};
}

OcclusionMeasure read_occlusion(const JsonReader& r, const json& o, const std::string& p) {
  OcclusionMeasure m;
  m.visibility = r.string(o, p, "visibility");
  const std::string rp = p + "/reference";
  const json& ref = r.object(o, p, "reference");
  m.reference_rsm_stride = r.uint32(ref, rp, "rsm_stride");
  m.reference_rsm_side = r.uint32(ref, rp, "rsm_side");
  m.reference_vpls = r.uint64(ref, rp, "vpls");
  m.reference_seconds = r.number(ref, rp, "seconds");
  m.ladder = read_ladder(r, r.object(ref, rp, "ladder"), rp + "/ladder");
  const std::string gp = p + "/region";
  const json& region = r.object(o, p, "region");
  m.region_rule = r.string(region, gp, "rule");
  m.surface_pixels = r.uint64(region, gp, "surface_pixels");
  m.occluded_pixels = r.uint64(region, gp, "occluded_pixels");
  m.unshadowed_mean_luminance = r.number(region, gp, "unshadowed_mean_luminance");
  m.occluded_light_share = r.number(region, gp, "occluded_light_share");
  m.note = r.string(o, p, "note");
  m.frames = read_frame_errors(r, r.object(o, p, "frames"), p + "/frames");
  const std::string cp = p + "/control";
  const json& control = r.object(o, p, "control");
  m.control_frames = r.uint32(control, cp, "frames");
  const json& errors = r.object(control, cp, "relative_rmse");
  for (const auto& item : errors.items()) m.control[item.key()] = r.numbers(errors, cp + "/relative_rmse", item.key());
  return m;
}

json k_sweep_json(const std::vector<std::pair<std::string, std::vector<KSweepRow>>>& k_sweep) {
  json sweep = json::object();
  for (const auto& [name, rows] : k_sweep) {
    json out = json::array();
    for (const KSweepRow& row : rows) {
      json r{{"K", row.K},
             {"frames", row.frames},
             {"weighted_cv", row.weighted_cv},
             {"power_stdev", row.power_stdev},
             {"power_relative_stdev", row.power_relative_stdev},
             {"error", error_json(row.error)},
             {"coverage", coverage_json(row.coverage)},
             {"power", power_json(row.power)}};
      if (!row.per_frame.empty()) r["per_frame"] = series_json(row.per_frame);
      if (!row.per_frame_second_rung.empty()) r["per_frame_second_rung"] = series_json(row.per_frame_second_rung);
      if (!row.per_frame_coarse_rungs.empty())
        r["per_frame_coarse_rungs"] = series_list_json(row.per_frame_coarse_rungs);
      out.push_back(r);
    }
    sweep[name] = out;
  }
  return sweep;
}

}  // namespace

void to_json(json& j, const QualityModel& m) {
  json config = m.config_rest;
  config["generators"] = m.generators;
  config["light_vsgls"] = m.light_vsgls;
  config["camera_vsgls"] = m.camera_vsgls;
  config["K"] = m.K;
  config["frames"] = m.frames;
  j = json{
      {"schema", m.schema},
      {"schema_version", m.schema_version},
      {"scene", m.scene},
      {"capture",
       json{{"path", m.capture_path}, {"gbuffer", m.gbuffer_size}, {"rsm", m.rsm_size}, {"hashes", m.capture_hashes}}},
      {"device", json{{"name", m.device_name}, {"driver", m.device_driver}}},
      {"build", to_json(m.build)},
      {"config", config},
      {"views", json::object()},
      {"reference", json{{"rsm_stride", m.reference_rsm_stride},
                         {"reference_rsm_side", m.reference_rsm_side},
                         {"vpls", m.reference_vpls},
                         {"power_ratio", m.reference_power_ratio},
                         {"image", m.reference_image},
                         {"method", m.reference_method}}},
      {"reference_error", json::object()}};
  for (const auto& [name, v] : m.views) j["views"][name] = view_json(v);
  for (const auto& [name, e] : m.reference_error) j["reference_error"][name] = error_json(e);
  if (m.reference_detail) j["reference"].update(reference_detail_json(*m.reference_detail));
  if (!m.reference_vpl_source.is_null()) j["reference"]["vpl_source"] = m.reference_vpl_source;
  if (!m.reference_error_support.empty()) {
    json support = json::object();
    for (const auto& [name, e] : m.reference_error_support) support[name] = error_json(e);
    j["reference_error_support"] = support;
  }
  json fs = json::object();
  for (const auto& [name, f] : m.flicker_static)
    fs[name] = json{{"frames", f.frames},
                    {"weighted_cv", f.weighted_cv},
                    {"power_stdev", f.power_stdev},
                    {"power_relative_stdev", f.power_relative_stdev}};
  j["flicker_static"] =
      json{{"image", m.flicker_image}, {"gbuffer_stride", m.flicker_gbuffer_stride}, {"generators", fs}};
  if (m.flicker_animated) j["flicker_animated"] = animated_json(*m.flicker_animated);
  j["k_sweep"] = k_sweep_json(m.k_sweep);
  if (m.frames_static) j["frames_static"] = frame_errors_json(*m.frames_static);
  if (m.frames_animated) j["frames_animated"] = frame_errors_json(*m.frames_animated);
  if (m.occlusion) j["occlusion"] = occlusion_json(*m.occlusion);
  if (m.claims) {
    json claims = json::array();
    for (const Claim& c : *m.claims) claims.push_back(to_json(c, ClaimLayout::kQuality));
    j["claims"] = claims;
  }
  json timings = json::object();
  for (const auto& [k, v] : m.timings_s) timings[k] = v;
  j["timings_s"] = timings;
  j = sorted_keys(j);  // as the document was always written
}

namespace {

// What was measured: the capture, the device, the build and the configuration.
void read_header(const JsonReader& r, const json& doc, QualityModel& m) {
  m.schema_version = r.member(doc, "", "schema_version");
  m.schema = r.string(doc, "", "schema");
  m.scene = r.string(doc, "", "scene");
  const json& capture = r.object(doc, "", "capture");
  m.capture_path = r.string(capture, "/capture", "path");
  m.gbuffer_size = r.array(capture, "/capture", "gbuffer", 2);
  m.rsm_size = r.array(capture, "/capture", "rsm", 2);
  m.capture_hashes = r.member(capture, "/capture", "hashes");
  const json& device = r.object(doc, "", "device");
  m.device_name = r.string(device, "/device", "name");
  m.device_driver = r.string(device, "/device", "driver");
  m.build = build_record_from_json(r, r.member(doc, "", "build"), "/build");
  const json& config = r.object(doc, "", "config");
  const json& gens = r.member(config, "/config", "generators");
  if (!gens.is_array()) r.wrong_type(gens, "/config/generators", "an array");
  for (std::size_t i = 0; i < gens.size(); ++i) {
    if (!gens[i].is_string()) r.wrong_type(gens[i], r.element("/config/generators", i), "a string");
    m.generators.push_back(gens[i].get<std::string>());
  }
  m.light_vsgls = r.member(config, "/config", "light_vsgls");
  m.camera_vsgls = r.member(config, "/config", "camera_vsgls");
  m.K = r.member(config, "/config", "K");
  m.frames = r.member(config, "/config", "frames");
  m.config_rest = config;
  for (const char* typed : {"generators", "light_vsgls", "camera_vsgls", "K", "frames"}) m.config_rest.erase(typed);
}

// The reference, and each generator's error against it at offset 0.
void read_reference(const JsonReader& r, const json& doc, QualityModel& m) {
  const json& ref = r.object(doc, "", "reference");
  m.reference_power_ratio = r.number(ref, "/reference", "power_ratio");
  m.reference_method = r.string(ref, "/reference", "method");
  m.reference_vpls = r.member(ref, "/reference", "vpls");
  m.reference_rsm_side = r.member(ref, "/reference", "reference_rsm_side");
  m.reference_rsm_stride = r.member(ref, "/reference", "rsm_stride");
  m.reference_image = r.array(ref, "/reference", "image", 2);
  if (ref.contains("vpl_source")) m.reference_vpl_source = r.object(ref, "/reference", "vpl_source");
  // Schema 6 judges the reference-decided claims by the ladder, so it must be there (DESIGN.md §11a).
  const bool ladder_required = m.schema_version.is_number_integer() && m.schema_version.get<int64_t>() >= 6;
  if (ref.contains("convergence")) m.reference_detail = read_reference_detail(r, ref, ladder_required);
  if (doc.contains("reference_error_support"))
    for (const auto& [g, e] : r.object(doc, "", "reference_error_support").items())
      m.reference_error_support[g] =
          read_error(r, r.object(r.object(doc, "", "reference_error_support"), "/reference_error_support", g),
                     "/reference_error_support/" + g);
  const json& errors = r.object(doc, "", "reference_error");
  for (const std::string& g : m.generators)
    m.reference_error[g] = read_error(r, r.object(errors, "/reference_error", g), "/reference_error/" + g);
}

void read_static_flicker(const JsonReader& r, const json& doc, QualityModel& m) {
  const json& fs = r.object(doc, "", "flicker_static");
  m.flicker_image = r.array(fs, "/flicker_static", "image", 2);
  m.flicker_gbuffer_stride = r.uint32(fs, "/flicker_static", "gbuffer_stride");
  const json& fsg = r.object(fs, "/flicker_static", "generators");
  for (const std::string& g : m.generators) {
    const std::string p = "/flicker_static/generators/" + g;
    const json& f = r.object(fsg, "/flicker_static/generators", g);
    m.flicker_static[g] = {r.number(f, p, "weighted_cv"), r.number(f, p, "power_stdev"),
                           r.number(f, p, "power_relative_stdev"), r.uint32(f, p, "frames")};
  }
}

QualityModel::Animated read_animated(const JsonReader& r, const json& fa) {
  QualityModel::Animated a;
  a.frames = r.member(fa, "/flicker_animated", "frames");
  a.sequence = r.string(fa, "/flicker_animated", "sequence");
  a.note = r.string(fa, "/flicker_animated", "note");
  a.scene = r.string(fa, "/flicker_animated", "scene");
  a.gbuffer_stride = r.uint32(fa, "/flicker_animated", "gbuffer_stride");
  a.reference_rsm_stride = r.uint32(fa, "/flicker_animated", "reference_rsm_stride");
  const json& hashes = r.member(fa, "/flicker_animated", "frame_content_hashes");
  if (!hashes.is_array()) r.wrong_type(hashes, "/flicker_animated/frame_content_hashes", "an array");
  for (std::size_t i = 0; i < hashes.size(); ++i) {
    if (!hashes[i].is_string())
      r.wrong_type(hashes[i], r.element("/flicker_animated/frame_content_hashes", i), "a string");
    a.frame_content_hashes.push_back(hashes[i].get<std::string>());
  }
  a.reference_weighted_cv = r.number(fa, "/flicker_animated", "reference_weighted_cv");
  const json& ag = r.object(fa, "/flicker_animated", "generators");
  for (const auto& [g, f] : ag.items()) {
    const std::string p = "/flicker_animated/generators/" + g;
    if (!f.is_object()) r.wrong_type(f, p, "an object");
    a.generators[g] = {r.number(f, p, "weighted_cv"), r.number(f, p, "error_cv"),
                       r.number(f, p, "power_relative_stdev")};
  }
  return a;
}

std::vector<KSweepRow> read_k_sweep_rows(const JsonReader& r, const json& rows, const std::string& gp) {
  if (!rows.is_array()) r.wrong_type(rows, gp, "an array");
  std::vector<KSweepRow> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string p = r.element(gp, i);
    const json& row = rows[i];
    if (!row.is_object()) r.wrong_type(row, p, "an object");
    out.push_back({r.number(row, p, "K"),
                   r.number(row, p, "weighted_cv"),
                   r.number(row, p, "power_stdev"),
                   r.number(row, p, "power_relative_stdev"),
                   r.uint32(row, p, "frames"),
                   read_error(r, r.object(row, p, "error"), p + "/error"),
                   read_coverage(r, r.object(row, p, "coverage"), p + "/coverage"),
                   read_power(r, r.object(row, p, "power"), p + "/power"),
                   FrameSeries{},
                   FrameSeries{},
                   {}});
    if (const json* series = r.optional_object(row, p, "per_frame"))
      out.back().per_frame = read_series(r, *series, p + "/per_frame");
    if (const json* series = r.optional_object(row, p, "per_frame_second_rung"))
      out.back().per_frame_second_rung = read_series(r, *series, p + "/per_frame_second_rung");
    if (row.contains("per_frame_coarse_rungs"))
      out.back().per_frame_coarse_rungs = read_series_list(r, row, p, "per_frame_coarse_rungs");
  }
  return out;
}

}  // namespace

QualityModel quality_model_from_json(const json& doc, const std::string& what) {
  const JsonReader r(what, JsonPathStyle::kPointer);
  if (!doc.is_object()) r.fail("", "is not a JSON object");
  QualityModel m;
  read_header(r, doc, m);
  const json& views = r.object(doc, "", "views");
  for (const char* view : {"camera_view", "light_view"})
    m.views[view] = read_view(r, r.object(views, "/views", view), std::string("/views/") + view);
  read_reference(r, doc, m);
  read_static_flicker(r, doc, m);
  if (doc.contains("flicker_animated")) m.flicker_animated = read_animated(r, r.object(doc, "", "flicker_animated"));
  if (doc.contains("k_sweep"))
    for (const auto& [g, rows] : r.object(doc, "", "k_sweep").items())
      m.k_sweep.emplace_back(g, read_k_sweep_rows(r, rows, "/k_sweep/" + g));
  if (const json* f = r.optional_object(doc, "", "frames_static"))
    m.frames_static = read_frame_errors(r, *f, "/frames_static");
  if (const json* f = r.optional_object(doc, "", "frames_animated"))
    m.frames_animated = read_frame_errors(r, *f, "/frames_animated");
  if (const json* o = r.optional_object(doc, "", "occlusion")) m.occlusion = read_occlusion(r, *o, "/occlusion");
  if (doc.contains("claims")) {
    const json& claims = r.array(doc, "", "claims");
    m.claims.emplace();
    for (std::size_t i = 0; i < claims.size(); ++i)
      m.claims->push_back(claim_from_json(r, claims[i], r.element("/claims", i), ClaimLayout::kQuality));
  }
  if (doc.contains("timings_s"))
    for (const auto& [k, v] : r.object(doc, "", "timings_s").items())
      m.timings_s.emplace_back(k, r.number(v, "/timings_s/" + k));
  return m;
}

}  // namespace vsgl
