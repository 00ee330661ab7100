#include "harness/quality/quality_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "harness/core/error.hpp"
#include "harness/core/generator_ids.hpp"
#include "harness/core/statistics.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;
using ojson = nlohmann::ordered_json;

// The two FIS generators every quality claim compares (core/generator_ids.hpp).
const std::string kTok15(kFisTok15), kModified(kFisModified);

std::string num(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

namespace {

void write_heading(std::ostringstream& md, const QualityModel& m) {
  md << "# Quality: " << m.scene << "\n\n";
  md << "Capture `" << m.capture_path << "` (G-buffer " << m.gbuffer_size[0] << "x" << m.gbuffer_size[1] << ", RSM "
     << m.rsm_size[0] << "^2), device " << m.device_name << ", vsgl-bench " << m.build.vsgl_bench_version << " (commit "
     << m.build.git_commit << (m.build.git_dirty ? ", dirty" : "") << "). N = " << m.light_vsgls << " (light view), "
     << m.camera_vsgls << " (camera view), K = " << m.K << ". Schema `vsgl-quality` v" << m.schema_version
     << "; every number is in `quality.json`.\n\n";
}

// A claim's numbers: the two means, and for a paired claim its estimate, interval and bound.
std::string measured_cell(const Claim& c) {
  if (c.measured.contains("steps")) {
    std::string out;
    for (const auto& step : c.measured.at("steps")) {
      const auto interval = [](const ojson& j) {
        if (!j.contains("interval")) return std::string("no interval");
        return num(j.at("estimate").get<double>()) + " [" + num(j.at("interval")[0].get<double>()) + ", " +
               num(j.at("interval")[1].get<double>()) + "]";
      };
      out += (out.empty() ? "" : "; ") + std::string("K ") + num(step.at("from_K").get<double>()) + " -> " +
             num(step.at("to_K").get<double>()) + ": flicker " + interval(step.at("flicker")) + ", error " +
             interval(step.at("error"));
    }
    return out;
  }
  std::string out;
  for (const auto& [key, value] : c.measured.items())
    if (key.find('_') != std::string::npos && value.is_number() &&
        (key.rfind("fis_", 0) == 0 || key.rfind("kmeans_", 0) == 0))
      out += (out.empty() ? "" : ", ") + key + " " + num(value.get<double>());
  if (c.measured.contains("interval"))
    out += "; " + c.measured.at("quantity").get<std::string>() + " " + num(c.measured.at("estimate").get<double>()) +
           " [" + num(c.measured.at("interval")[0].get<double>()) + ", " +
           num(c.measured.at("interval")[1].get<double>()) + "], claimed " +
           c.measured.at("claimed_side").get<std::string>() + " " + num(c.measured.at("bound").get<double>());
  return out;
}

bool has_ladder(const QualityModel& m) { return m.reference_detail && m.reference_detail->ladder; }

// Schema 7 judges a reference-decided claim by its own movement over the ladder's rungs.
bool judged_by_own_ladder(const QualityModel& m) {
  return m.schema_version.is_number_integer() && m.schema_version.get<int64_t>() >= 7;
}

// The rule of DESIGN.md §11a in one sentence (schema 7).
constexpr const char* kOwnLadderRule =
    "A claim on an error against the reference is decided only where its 95 % interval, widened on each side by "
    "how far the claim may still move as the reference's RSM side doubles (delta_inf = max_t s_t rho^t rho / (1 - "
    "rho), s_t the claim's steps between the rungs of the ladder counted from the finest, rho the metric's rate), "
    "gives the same verdict, and where its verdict against the reference's stride-2 rung is the same; otherwise it "
    "is \"reference not converged\".";
// Schema 6's rule, by which its documents' verdicts were judged and are kept.
constexpr const char* kLadderRule =
    "A claim on an error against the reference is decided only where (1 + b) eps_inf (2 eps_inf for a difference) "
    "is below its distance |mean_a - b mean_b| from the bound b, eps_inf = own rho / (1 - rho) the reference's "
    "remaining error in that metric from its ladder's rate rho per doubling, and where its verdict against the "
    "reference's stride-2 rung is the same; otherwise it is \"reference not converged\".";

void write_claims(std::ostringstream& md, const QualityModel& m) {
  md << "## Claims\n\n| claim | measure | measured (95 % interval) | verdict |\n|---|---|---|---|\n";
  for (const Claim& c : m.claims.value_or(std::vector<Claim>{}))
    md << "| " << c.text << " | " << c.criterion << " | " << measured_cell(c) << " | **" << stated_verdict(c)
       << "** |\n";
  md << "\nEach claim compares per-frame values paired by frame (the same lattice offset, or the same animation "
        "frame): the interval is the paired percentile bootstrap of the ratio of means (the difference for the "
        "coverage excess), and a claim holds when the whole interval lies on the claimed side of its bound, does "
        "not hold when it lies wholly on the other side, and is inconclusive otherwise (DESIGN.md §11a.1). ";
  if (judged_by_own_ladder(m)) md << kOwnLadderRule << "\n";
  else if (has_ladder(m)) md << kLadderRule << "\n";
  else  // schema 5: its verdicts were judged by the rule of its time, kept as written
    md << "A claim on an error against the reference is decided only when the reference's own error in that metric "
          "is below a tenth of the measured distance from the bound.\n";
}

void write_frequency(std::ostringstream& md, const QualityModel& m) {
  md << "\n## How high-frequency the PDFs are\n\nHaar wavelet spectrum on the mip levels: share of the PDF's "
        "energy mean(p^2) (p normalized to mean 1 over the virtual square) at wavelengths below 2^(k+1) texels "
        "(`pdf_frequency` in the JSON: 0 for a uniform PDF, about 0.5 for a texel checkerboard of 1 and 0).\n\n"
        "| view | relative variance | < 2 texels | < 4 | < 8 | < the mean kernel side | mean kernel side (texels) "
        "|\n|---|---|---|---|---|---|---|\n";
  for (const char* view : {"light_view", "camera_view"}) {
    if (!m.views.at(view).pdf_frequency) continue;
    const PdfFrequencySummary& f = *m.views.at(view).pdf_frequency;
    const auto share = [&](std::size_t k) { return k < f.fine_share.size() ? num(f.fine_share[k]) : std::string("n/a"); };
    md << "| " << view << " | " << num(f.relative_variance) << " | " << share(0) << " | " << share(1) << " | " << share(2)
       << " | " << num(f.share_below_kernel) << " (< " << num(f.share_below_kernel_side_texels) << ") | "
       << num(f.mean_kernel_side_texels) << " |\n";
  }
}

// One metric of a generator on a view; coverage metrics are n/a for k-means.
using CoverageCell = std::function<std::string(const CoverageSummary&)>;

void write_view(std::ostringstream& md, const QualityModel& m, const std::string& view) {
  const ViewQuality& v = m.views.at(view);
  md << "\n## " << view << " (N = " << v.vsgls << ", total flux " << num(v.total_flux) << ")\n\n| metric |";
  for (const auto& g : m.generators) md << " " << g << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < m.generators.size(); ++i) md << "---|";
  md << "\n";
  const auto row = [&](const std::string& label, const std::function<std::string(const GeneratorQuality&)>& cell) {
    md << "| " << label << " |";
    for (const auto& g : m.generators) md << " " << cell(v.generators.at(g)) << " |";
    md << "\n";
  };
  const auto cov = [&](const std::string& label, const CoverageCell& cell) {
    row(label, [&](const GeneratorQuality& g) { return g.coverage ? cell(*g.coverage) : std::string("n/a"); });
  };
  const auto power = [&](const std::string& label, double PowerSummary::*field) {
    row(label, [&](const GeneratorQuality& g) { return num(g.power.*field); });
  };
  cov("gap (PDF-weighted, box)", [](const CoverageSummary& c) { return num(c.gap); });
  cov("overlap n >= 2 (PDF-weighted, box)", [](const CoverageSummary& c) { return num(c.overlap); });
  cov("gap + overlap (box)", [](const CoverageSummary& c) { return num(c.gap_plus_overlap); });
  cov("lattice floor: gap, box", [](const CoverageSummary& c) { return num(c.floor_box.gap); });
  cov("lattice floor: overlap, box", [](const CoverageSummary& c) { return num(c.floor_box.overlap.value_or(0.0)); });
  cov("count-weighted error sum q|n-1|/sum q, box", [](const CoverageSummary& c) { return num(c.box.count_error); });
  cov("... lattice floor, box", [](const CoverageSummary& c) { return num(c.floor_box.count_error); });
  cov("... excess over the floor, box", [](const CoverageSummary& c) { return num(c.excess_box.count_error); });
  cov("count-weighted error, Eq. 3 footprint", [](const CoverageSummary& c) { return num(c.eq3.count_error); });
  cov("... lattice floor, Eq. 3", [](const CoverageSummary& c) { return num(c.floor_eq3.count_error); });
  cov("... **excess over the floor, Eq. 3 (the verdict)**", [](const CoverageSummary& c) { return num(c.excess_eq3.count_error); });
  cov("gap / surplus, Eq. 3", [](const CoverageSummary& c) { return num(c.eq3.gap) + " / " + num(c.eq3.surplus); });
  cov("PDF-weighted mean n, Eq. 3", [](const CoverageSummary& c) { return num(c.eq3.mean_count); });
  cov("kernel mass / (K/N): mean", [](const CoverageSummary& c) { return num(c.mass_over_target.mean); });
  cov("kernel mass / (K/N): stdev", [](const CoverageSummary& c) { return num(c.mass_over_target.stdev); });
  cov("kernel mass / (K/N): min", [](const CoverageSummary& c) { return num(c.mass_over_target.min); });
  cov("kernel mass / (K/N): max", [](const CoverageSummary& c) { return num(c.mass_over_target.max); });
  power("max Phi_i / mean", &PowerSummary::max_over_mean);
  power("p99 Phi_i / mean", &PowerSummary::p99_over_mean);
  power("sum Phi / total flux", &PowerSummary::power_ratio);
}

// Where the VSGLs' power comes from (schema 4; flux_origin.hpp): nothing for older documents.
void write_flux_origin(std::ostringstream& md, const QualityModel& m) {
  double oversized_mass = 0;
  bool any = false;
  for (const auto& [name, v] : m.views)
    if (v.flux_by_pdf) {
      any = true;
      oversized_mass = v.flux_by_pdf->oversized_mass;
    }
  if (!any) return;
  md << "\n## Where the power comes from\n\nEach texel t's flux f(t) enters the VSGLs' total power c(t) times, "
        "c(t) = sum_i M w_i(t) / D_i (w_i: kernel i's trilinear weights, D_i the density its power divides by), so "
        "sum Phi = sum_t f(t) c(t). Texels are classed by their expected number of kernel centres e = N q / sum q; "
        "each cell is a share of the view's flux: what the class holds, and what enters the power from it "
        "(of that, from kernels holding more than "
     << num(oversized_mass)
     << " times their stratum's probability). PDF-weighted mean c: sum q c / sum q, exactly 1 for Eq. 5.\n";
  for (const char* view : {"light_view", "camera_view"}) {
    const ViewQuality& v = m.views.at(view);
    if (!v.flux_by_pdf) continue;
    const FluxByPdfSummary& f = *v.flux_by_pdf;
    const auto label = [&](std::size_t c) {
      if (c == 0) return std::string("q = 0");
      if (c == 1) return "e < " + num(f.bounds.front());
      if (c > f.bounds.size()) return "e >= " + num(f.bounds.back());
      return num(f.bounds[c - 2]) + " <= e < " + num(f.bounds[c - 1]);
    };
    md << "\n" << view << ":\n\n| texels | count | flux |";
    std::vector<std::string> fis;
    for (const auto& g : m.generators)
      if (v.generators.at(g).flux_origin) {
        fis.push_back(g);
        md << " " << g << " gathers (oversized) |";
      }
    md << "\n|---|---|---|";
    for (std::size_t i = 0; i < fis.size(); ++i) md << "---|";
    md << "\n";
    for (std::size_t c = 0; c < f.flux_share.size(); ++c) {
      md << "| " << label(c) << " | " << f.texels.at(c) << " | " << num(f.flux_share[c]) << " |";
      for (const auto& g : fis) {
        const FluxOriginSummary& o = *v.generators.at(g).flux_origin;
        md << " " << num(o.gathered.at(c)) << " (" << num(o.gathered_by_oversized.at(c)) << ") |";
      }
      md << "\n";
    }
    md << "| sum Phi / flux (attributed) | | 1 |";
    for (const auto& g : fis) md << " " << num(v.generators.at(g).flux_origin->attributed_power_ratio) << " |";
    md << "\n| PDF-weighted mean c | | |";
    for (const auto& g : fis) md << " " << num(v.generators.at(g).flux_origin->pdf_weighted_count) << " |";
    md << "\n| oversized kernels | | |";
    for (const auto& g : fis) md << " " << num(v.generators.at(g).flux_origin->oversized_kernels) << " |";
    md << "\n";
    for (const auto& g : fis) {
      const auto& frames = v.generators.at(g).flux_origin->over_frames;
      if (!frames) continue;
      md << "\n"
         << g << " over " << frames->frames << " lattice offsets: sum Phi / flux mean " << num(frames->ratio_mean)
         << " (stdev " << num(frames->ratio_stdev) << ", " << num(frames->ratio_min) << " to " << num(frames->ratio_max)
         << "), share of the power from oversized kernels " << num(frames->oversized_share_mean)
         << "; per class (mean, stdev):";
      for (std::size_t c = 0; c < frames->gathered_mean.size(); ++c)
        md << (c == 0 ? " " : ", ") << num(frames->gathered_mean[c]) << " (" << num(frames->gathered_stdev[c]) << ")";
      md << ".\n";
    }
  }
}

// Whose RSM the reference's VPLs come from: the capture's, or a reference capture's larger one.
std::string vpl_source_text(const nlohmann::ordered_json& source) {
  if (source.is_null()) return "RSM";  // schema 5 documents written before vpl_source
  if (source.value("capture", "") != "reference capture") return "the capture's RSM";
  const auto& rsm = source.at("rsm");
  return "the " + rsm[0].dump() + "x" + rsm[1].dump() + " RSM of the reference capture " +
         source.value("path", std::string("?"));
}

// A ladder value: "inf" or "n/a" where it is not finite (no rate; rho >= 1).
std::string ladder_num(double v, const char* otherwise) { return std::isfinite(v) ? num(v) : std::string(otherwise); }

// The reference ladder (DESIGN.md §11a, schema 6): per pair of neighbouring rungs the successive
// difference and its ratio to the previous one in each metric, then rho and eps_inf, and the rule.
void write_ladder(std::ostringstream& md, const ReferenceLadder& l, const char* rule) {
  md << ".\n\nReference ladder: each rung (RSM stride, side) against the next finer one, same pixels; ratio: "
        "this difference over the one above. "
     << l.note << ".\n\n| rungs |";
  for (const auto& [metric, lm] : l.metrics) md << " " << metric << " | ratio |";
  md << "\n|---|";
  for (std::size_t i = 0; i < l.metrics.size(); ++i) md << "---|---|";
  md << "\n";
  const auto rung = [&](std::size_t i) {
    return std::to_string(l.rsm_strides.at(i)) + " (" + std::to_string(l.rsm_sides.at(i)) + "^2)";
  };
  const auto cell = [](const std::string& text) { return text.empty() ? std::string(" |") : " " + text + " |"; };
  for (std::size_t i = 0; i + 1 < l.rsm_strides.size(); ++i) {
    md << "| " << rung(i) << " vs " << rung(i + 1) << (i + 2 == l.rsm_strides.size() ? ", the own error" : "") << " |";
    for (const auto& [metric, lm] : l.metrics)
      md << cell(i < lm.differences.size() ? num(lm.differences[i]) : std::string("n/a"))
         << cell(i >= 1 && i - 1 < lm.ratios.size() ? ladder_num(lm.ratios[i - 1], "n/a") : std::string());
    md << "\n";
  }
  md << "| rate rho per doubling (geometric mean of the ratios) |";
  for (const auto& [metric, lm] : l.metrics) md << " " << ladder_num(lm.rate, "none") << " | |";
  md << "\n| remaining error eps_inf = own rho / (1 - rho) |";
  for (const auto& [metric, lm] : l.metrics) md << " " << ladder_num(lm.remaining, "inf") << " | |";
  md << "\n";
  if (!l.mean_luminances.empty()) {
    // Flat where the reference converges; rising with the RSM where light leaks (DESIGN.md §11a).
    md << "\nMean luminance of the pixels with a surface, per rung:";
    for (std::size_t i = 0; i < l.mean_luminances.size() && i < l.rsm_strides.size(); ++i)
      md << (i == 0 ? " " : ", ") << rung(i) << " " << num(l.mean_luminances[i]);
    md << ".\n";
  }
  md << "\n" << rule << "\n\n";
}

void write_reference_error(std::ostringstream& md, const QualityModel& m) {
  md << "\n## Error against the reference (light-view VSGLs lighting the camera view)\n\n";
  // The shading model the document was made with (schema 6 records it in the config).
  if (const auto it = m.config_rest.find("shading"); it != m.config_rest.end() && it->is_object() &&
                                                      it->contains("text") && (*it)["text"].is_string())
    md << "Shading: " << (*it)["text"].get<std::string>() << ".\n\n";
  md << "Reference: "
     << m.reference_vpls << " VPLs (" << vpl_source_text(m.reference_vpl_source) << " subsampled to "
     << m.reference_rsm_side << "^2, stride " << m.reference_rsm_stride << ", sum Phi / flux "
     << num(m.reference_power_ratio) << "), image " << m.reference_image[0] << "x" << m.reference_image[1] << ". "
     << m.reference_method
     << ". p99 pixel error: 99th percentile of |dY| / mean Y(reference).\n\n| generator | relative RMSE | p99 pixel "
        "error |\n|---|---|---|\n";
  for (const auto& g : m.generators)
    md << "| " << g << " | " << num(m.reference_error.at(g).relative_rmse) << " | " << num(m.reference_error.at(g).p99_pixel_error)
       << " |\n";
  if (!m.reference_detail) return;
  const ReferenceDetail& d = *m.reference_detail;
  md << "\nCamera size: G-buffer stride " << d.error_stride << " (" << d.camera_size_rule << "; budget "
     << num(d.budget_s) << " s";
  if (d.predicted_full_size_s) md << ", predicted at full size " << num(*d.predicted_full_size_s) << " s";
  md << "). Dispatches of at most " << d.evaluations_per_dispatch << " VSGL evaluations (" << d.vsgls_per_dispatch
     << " VSGLs each here). Convergence, same pixels:\n\n| RSM stride | VPLs | relative RMSE against the reference | "
        "seconds |\n|---|---|---|---|\n";
  for (const ReferenceConvergenceRow& r : d.convergence)
    md << "| " << r.rsm_stride << " | " << r.vpls << " | " << num(r.relative_rmse) << " | " << num(r.seconds) << " |\n";
  md << "\nThe reference's own error (the next coarser stride against it): " << num(d.own_error);
  for (const auto& [metric, e] : d.own_errors)
    md << (metric == d.own_errors.begin()->first ? " (" : ", ") << metric << " " << num(e);
  if (!d.own_errors.empty()) md << ")";
  if (d.ladder) write_ladder(md, *d.ladder, judged_by_own_ladder(m) ? kOwnLadderRule : kLadderRule);
  else  // schema 5: the rule its verdicts were judged by
    md << "; a difference it judges must exceed ten times that, or the verdict is \"reference not converged\".\n\n";
  md << "PDF-support reference (texels with PDF > 0 only): " << d.support_vpls << " VPLs, sum Phi / flux "
     << num(d.support_power_ratio) << ", relative RMSE against the all-lit "
     << "reference " << num(d.support_vs_all_lit) << ", " << num(d.support_seconds)
     << " s.\n\n| generator | relative RMSE against the support reference | p99 pixel error |\n|---|---|---|\n";
  for (const auto& g : m.generators)
    if (m.reference_error_support.count(g) != 0)
      md << "| " << g << " | " << num(m.reference_error_support.at(g).relative_rmse) << " | "
         << num(m.reference_error_support.at(g).p99_pixel_error) << " |\n";
}

// Every frame's image error (schema 5): each metric's mean / p95 / max over the frames.
void write_frame_errors(std::ostringstream& md, const QualityModel& m, const FrameErrors& f, const std::string& title) {
  md << "\n## Image error per frame, " << title << " (image " << f.image[0] << "x" << f.image[1] << ", G-buffer stride "
     << f.gbuffer_stride << ")\n\nAgainst " << f.reference << ". Each cell: mean / 95th percentile / maximum over the "
     << "frames. relMSE = mean (dY)^2 / (Y_ref^2 + 0.01 mean(Y_ref)^2); scale s* = sum L.R / sum L.L and the "
        "relative RMSE of s* L; FLIP at exposure "
     << num(f.flip_exposure) << " stops, " << num(f.flip_pixels_per_degree)
     << " pixels per degree; pixel errors |dY| / mean Y_ref (DESIGN.md §11a.1).\n\n| metric |";
  std::vector<std::string> gens;
  for (const auto& g : m.generators)
    if (f.generators.contains(g)) gens.push_back(g);
  for (const auto& g : gens) md << " " << g << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < gens.size(); ++i) md << "---|";
  md << "\n";
  for (const char* metric : {"rel_mse", "relative_rmse", "scaled_rmse", "scale", "flip", "p99_pixel_error",
                             "max_pixel_error", "flicker_deviation", "error_flicker_deviation"}) {
    bool any = false;
    for (const auto& g : gens) any = any || f.generators.at(g).contains(metric);
    if (!any) continue;
    md << "| " << metric << " |";
    for (const auto& g : gens) {
      const auto it = f.generators.at(g).find(metric);
      if (it == f.generators.at(g).end()) {
        md << " n/a |";
        continue;
      }
      const SampleStats sum = summarize(it->second);
      md << " " << num(sum.mean) << " / " << num(sum.p95) << " / " << num(sum.max) << " |";
    }
    md << "\n";
  }
  md << "| worst frame (largest relative RMSE) |";
  for (const auto& g : gens) {
    const auto it = f.generators.at(g).find("relative_rmse");
    md << " "
       << (it == f.generators.at(g).end()
               ? std::string("n/a")
               : std::to_string(std::max_element(it->second.begin(), it->second.end()) - it->second.begin()))
       << " |";
  }
  md << "\n";
}

void write_flicker(std::ostringstream& md, const QualityModel& m) {
  md << "\n## Flicker, static scene (" << m.frames << " frames, only the lattice offset changes; image " << m.flicker_image[0]
     << "x" << m.flicker_image[1] << ")\n\n| generator | weighted temporal CV | stdev of total power | "
                                     "relative stdev of total power |\n|---|---|---|---|\n";
  for (const auto& g : m.generators) {
    const StaticFlicker& f = m.flicker_static.at(g);
    md << "| " << g << " | " << num(f.weighted_cv) << " | " << num(f.power_stdev) << " | " << num(f.power_relative_stdev) << " |\n";
  }
  if (!m.flicker_animated) {
    md << "\n## Flicker, animated sequence\n\nNot run (no `--sequence DIR`).\n";
    return;
  }
  const QualityModel::Animated& fa = *m.flicker_animated;
  md << "\n## Flicker, animated sequence (" << fa.frames << " frames of `" << fa.sequence << "`; light and camera move)\n\n"
     << fa.note << ". Reference weighted CV " << num(fa.reference_weighted_cv)
     << ".\n\n| generator | weighted temporal CV | error CV | relative stdev of total power |\n|---|---|---|---|\n";
  for (const auto& g : m.generators) {
    const AnimatedFlicker& f = fa.generators.at(g);
    md << "| " << g << " | " << num(f.weighted_cv) << " | " << num(f.error_cv) << " | " << num(f.power_relative_stdev) << " |\n";
  }
}

void write_k_sweep(std::ostringstream& md, const QualityModel& m) {
  md << "\n## K sweep (Fig. 6)\n\nOffset 0, and the mean over the static frames (schema 5).\n\n| generator | K | "
        "weighted CV "
        "| frame flicker, mean | relative RMSE | relative RMSE, frame mean | p99 pixel error | gap + overlap | "
        "count error, Eq. 3 (floor) | max Phi_i / mean |\n|---|---|---|---|---|---|---|---|---|---|\n";
  const auto frame_mean = [](const KSweepRow& row, const char* series) {
    const auto it = row.per_frame.find(series);
    return it == row.per_frame.end() ? std::string("n/a") : num(summarize(it->second).mean);
  };
  for (const auto& [g, rows] : m.k_sweep)
    for (const KSweepRow& row : rows)
      md << "| " << g << " | " << num(row.K) << " | " << num(row.weighted_cv) << " | "
         << frame_mean(row, "flicker_deviation") << " | " << num(row.error.relative_rmse) << " | "
         << frame_mean(row, "relative_rmse") << " | " << num(row.error.p99_pixel_error) << " | "
         << num(row.coverage.gap_plus_overlap) << " | " << num(row.coverage.eq3.count_error) << " ("
         << num(row.coverage.floor_eq3.count_error) << ") | " << num(row.power.max_over_mean) << " |\n";
}

}  // namespace

// Fig. 7 (DESIGN.md §11a.2): the occluded region, R_v's ladder over it, and each generator's error
// over it with the run's visibility beside the exact control.
void write_occlusion(std::ostringstream& md, const QualityModel& m) {
  if (!m.occlusion) return;
  const OcclusionMeasure& o = *m.occlusion;
  md << "\n## Fig. 7: the light occluded by the columns (DESIGN.md §11a.2)\n\nFrames shaded with " << o.visibility
     << ". Reference R_v: every lit texel of the RSM at stride " << o.reference_rsm_stride << " ("
     << o.reference_rsm_side << "^2, " << o.reference_vpls << " VPLs) traced to every pixel (" << o.frames.image[0]
     << "x" << o.frames.image[1] << ", G-buffer stride " << o.frames.gbuffer_stride << "), " << num(o.reference_seconds)
     << " s with its rungs. Occluded region O: " << o.region_rule << ": " << o.occluded_pixels << " of "
     << o.surface_pixels << " surface pixels, holding " << num(o.occluded_light_share)
     << " of the unshadowed light's luminance.";
  if (!o.note.empty()) md << " " << o.note << ".";
  md << "\n\nR_v's ladder, relative RMSE over O of each rung against the next finer one (RSM strides";
  for (uint32_t s : o.ladder.rsm_strides) md << " " << s;
  md << "):";
  if (const auto it = o.ladder.metrics.find("relative_rmse"); it != o.ladder.metrics.end()) {
    for (double d : it->second.differences) md << " " << num(d);
    md << "; rate per doubling " << (std::isfinite(it->second.rate) ? num(it->second.rate) : std::string("none"))
       << ".\n";
  } else {
    md << " none.\n";
  }
  if (o.frames.generators.empty()) return;
  md << "\n| generator | relative RMSE over O (mean / 95th percentile / maximum over the frames) | control: exact "
        "visibility from the VSGLs' means (first "
     << o.control_frames << " frame(s), mean) |\n|---|---|---|\n";
  for (const auto& g : m.generators) {
    const auto it = o.frames.generators.find(g);
    if (it == o.frames.generators.end() || !it->second.contains("relative_rmse")) continue;
    const SampleStats sum = summarize(it->second.at("relative_rmse"));
    md << "| " << g << " | " << num(sum.mean) << " / " << num(sum.p95) << " / " << num(sum.max) << " | ";
    const auto c = o.control.find(g);
    if (c != o.control.end() && !c->second.empty()) {
      double mean = 0;
      for (double v : c->second) mean += v;
      md << num(mean / static_cast<double>(c->second.size()));
    } else {
      md << "n/a";
    }
    md << " |\n";
  }
}

std::string quality_markdown(const QualityModel& m, const std::vector<QualityPicture>& pictures) {
  std::ostringstream md;
  write_heading(md, m);
  write_claims(md, m);
  write_frequency(md, m);
  for (const char* view : {"light_view", "camera_view"}) write_view(md, m, view);
  md << "\nCoverage is defined for the FIS generators only (a k-means cluster has no square footprint): n/a.\n";
  write_flux_origin(md, m);
  write_reference_error(md, m);
  if (m.frames_static) write_frame_errors(md, m, *m.frames_static, "static scene (lattice offsets)");
  if (m.frames_animated) write_frame_errors(md, m, *m.frames_animated, "animated sequence");
  write_flicker(md, m);
  write_k_sweep(md, m);
  write_occlusion(md, m);
  md << "\n## Pictures\n\n";
  for (const auto& p : pictures) md << "- `" << p.file << "`: " << p.description << "\n";
  md << "\n## Run time\n\n";
  for (const auto& [k, v] : m.timings_s) md << "- " << k << ": " << num(v) << " s\n";
  return md.str();
}

std::string quality_markdown(const json& r, const std::vector<QualityPicture>& pictures) {
  return quality_markdown(quality_model_from_json(r, "the quality document"), pictures);
}

}  // namespace vsgl
