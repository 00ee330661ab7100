#pragma once
// The quality JSON ("vsgl-quality", quality_run.hpp) as a typed model: what run_quality fills and
// writes with to_json, and what the markdown and the claim verdicts of quality_claims.hpp read,
// parsed once from the document with every missing or mistyped field named by its JSON pointer.
// Raw JSON members are provenance and configuration passed through as written.
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/claim.hpp"
#include "harness/formats/run_header.hpp"

namespace vsgl {

// Kernel counts n(t) against 1 on one footprint (DESIGN.md §11a); `overlap` on the box floor/excess.
struct CoverageCountsSummary {
  double gap = 0, surplus = 0, count_error = 0, mean_count = 0;
  std::optional<double> overlap;
};

struct MassSummary {
  double mean = 0, stdev = 0, min = 0, max = 0, p99 = 0;  // stdev: sample (n - 1) from schema 3
};

struct CoverageSummary {
  double gap = 0, overlap = 0, gap_plus_overlap = 0;
  uint64_t texels_with_pdf = 0, gap_texels = 0, overlap_texels = 0;
  MassSummary mass_over_target;
  CoverageCountsSummary box, eq3;
  CoverageCountsSummary floor_box, floor_eq3;    // lattice_floor
  CoverageCountsSummary excess_box, excess_eq3;  // excess over the floor
};

struct PowerSummary {
  double max_over_mean = 0, p99_over_mean = 0, power_ratio = 0;
  double sum_vsgl_power = 0, total_flux = 0;
};

// Where a FIS generator's power comes from (quality/flux_origin.hpp; schema 4): per class of
// texels by expected kernel centres, the flux each class gives the VSGLs, as a share of the view's.
// The same over the static frames (lattice offsets) of the light view: one offset's sum Phi / flux
// spreads by several percent where a few kernels carry much of the power.
struct FluxOriginFrames {
  uint32_t frames = 0;
  std::vector<double> gathered_mean, gathered_stdev;  // per class; stdev: sample (n - 1)
  double ratio_mean = 0, ratio_stdev = 0, ratio_min = 0, ratio_max = 0;
  double oversized_share_mean = 0;  // mean over frames of the power share of oversized kernels
};
struct FluxOriginSummary {
  std::vector<double> gathered, gathered_by_oversized;  // one per class of the view's flux_by_pdf
  double attributed_power_ratio = 0, pdf_weighted_count = 0, oversized_kernels = 0;
  std::optional<FluxOriginFrames> over_frames;  // light view, FIS generators
};

struct GeneratorQuality {
  std::optional<CoverageSummary> coverage;  // FIS generators only
  PowerSummary power;
  std::optional<FluxOriginSummary> flux_origin;  // FIS generators, schema 4
};

// A view's flux by its texels' expected number of kernel centres e = N q / sum q (schema 4):
// class 0 is PDF 0, then e < bounds[0], [bounds[0], bounds[1]), ..., e >= bounds.back().
struct FluxByPdfSummary {
  std::vector<double> bounds;
  std::vector<uint64_t> texels;  // texels with positive flux
  std::vector<double> flux_share;
  double oversized_mass = 0;  // the kernel mass over its target above which a kernel is "oversized"
  std::string definition;
};

struct PdfFrequencySummary {
  double relative_variance = 0;
  std::vector<double> fine_share;
  double share_below_kernel = 0, share_below_kernel_side_texels = 0, mean_kernel_side_texels = 0;
  std::vector<double> detail_energy;
  double mean_square = 0, share_below_8_texels = 0;
  std::string definition;
};

struct ViewQuality {
  nlohmann::ordered_json vsgls;  // N, printed as written
  double total_flux = 0;
  std::optional<PdfFrequencySummary> pdf_frequency;
  std::optional<FluxByPdfSummary> flux_by_pdf;  // schema 4
  std::map<std::string, GeneratorQuality> generators;
};

struct ImageErrorSummary {
  double relative_rmse = 0, p99_pixel_error = 0;
};

struct StaticFlicker {
  double weighted_cv = 0, power_stdev = 0, power_relative_stdev = 0;
  uint32_t frames = 0;
};

struct AnimatedFlicker {
  double weighted_cv = 0, error_cv = 0, power_relative_stdev = 0;
};

// Per-frame values (schema 5, DESIGN.md §11a.1): by measure ("relative_rmse", "flip",
// "flicker_deviation", "light_view_coverage_excess", ...), one value per frame, frames in order.
// Written with each series' mean, 95th percentile and maximum beside it (derived, not read back).
using FrameSeries = std::map<std::string, std::vector<double>>;

// Every frame's image error and flicker of each generator: the static frames (lattice offsets) or
// the animated sequence's.
struct FrameErrors {
  uint32_t gbuffer_stride = 0;
  nlohmann::ordered_json image;  // [w, h]
  std::string reference;  // what each frame is compared with
  double flip_exposure = 0, flip_pixels_per_degree = 0;
  std::map<std::string, FrameSeries> generators;
  // Schema 6, static frames: each generator's image error set against the reference's stride-2
  // rung, the same pixels, frames and FLIP exposure, for the rule's second verdict (DESIGN.md
  // §11a *Rule*); empty where there is no such rung, and for the animated frames.
  std::map<std::string, FrameSeries> second_rung;
  std::string second_rung_reference;  // what second_rung is compared with; "" where it is empty
  // Schema 7, static frames: the same against each rung coarser than the stride-2 one, coarsest
  // first, their RSM strides in coarse_rung_strides, so a reference-decided claim is computed
  // against every rung of the ladder (DESIGN.md §11a *Rule*); empty where the ladder has none.
  std::vector<uint32_t> coarse_rung_strides;
  std::map<std::string, std::vector<FrameSeries>> coarse_rungs;
};

struct KSweepRow {
  double K = 0, weighted_cv = 0;
  double power_stdev = 0, power_relative_stdev = 0;  // the row's static flicker, as flicker_static
  uint32_t frames = 0;
  ImageErrorSummary error;
  CoverageSummary coverage;
  PowerSummary power;
  FrameSeries per_frame;  // schema 5: "flicker_deviation" and "relative_rmse" over the static frames
  // Schema 6: "relative_rmse" of the same frames against the reference's stride-2 rung (the rule's
  // second verdict, DESIGN.md §11a); empty where there is no such rung.
  FrameSeries per_frame_second_rung;
  // Schema 7: the same against each coarser rung, in frames_static's coarse_rung_strides order.
  std::vector<FrameSeries> per_frame_coarse_rungs;
};

// The converged reference of schema 4 (DESIGN.md §11a): how far coarser RSM strides are from it,
// the PDF-support reference, the camera size and the chunking of its dispatches.
struct ReferenceConvergenceRow {
  uint32_t rsm_stride = 0;
  uint64_t vpls = 0;
  double relative_rmse = 0;  // against the reference (the finest stride), same pixels
  double seconds = 0;        // to shade it
};
// The reference ladder (DESIGN.md §11a, schema 6): the reference shaded at RSM strides 8, 4, 2 and 1
// of its own (the rungs), each rung against the next finer one on the same pixels. Per metric the
// successive differences, their ratios, the rate rho per doubling of the side and the remaining
// error eps_inf = own * rho / (1 - rho); quality/quality_reference.hpp computes them and decides by
// them. Non-finite values are written as null.
struct ReferenceLadderMetric {
  std::vector<double> differences;  // coarsest pair first; the last (stride 2 against 1) is the own error
  std::vector<double> ratios;       // differences[i + 1] / differences[i]
  double rate = std::numeric_limits<double>::quiet_NaN();      // rho; NaN where there is none
  double remaining = std::numeric_limits<double>::infinity();  // eps_inf; infinite where rho >= 1 or none
};
struct ReferenceLadder {
  std::vector<uint32_t> rsm_strides;  // the rungs, coarsest first, the reference's own stride last
  std::vector<uint32_t> rsm_sides;    // their RSM sides: the VPL source RSM's side / stride, rounded up
  // Each rung's mean luminance over the pixels with a surface (quality_metrics.hpp); empty in the
  // schema-6 documents written before it was recorded.
  std::vector<double> mean_luminances;
  std::map<std::string, ReferenceLadderMetric> metrics;  // by frame metric (frame_error.hpp)
  std::string note;                                      // how many rungs there were, and what that leaves decided
};

struct ReferenceDetail {
  std::vector<ReferenceConvergenceRow> convergence;  // coarsest first, the reference itself last
  double own_error = 0;  // the row at twice the reference's stride: the reference's own error
  // schema 5: that row's error in every frame metric (frame_error.hpp), the same pixels and exposure
  std::map<std::string, double> own_errors;
  double seconds = 0;    // shading the reference
  uint64_t support_vpls = 0;
  double support_power_ratio = 0, support_seconds = 0;
  double support_vs_all_lit = 0;  // relative RMSE of the support reference against the all-lit one
  uint32_t error_stride = 0;      // G-buffer stride of every reference comparison
  std::string camera_size_rule;
  double budget_s = 0;
  std::optional<double> predicted_full_size_s;  // when the size was chosen by the budget
  uint64_t evaluations_per_dispatch = 0;
  uint32_t vsgls_per_dispatch = 0;
  // Schema 6 (required there): the ladder the reference-decided claims are judged by. None in a
  // schema-5 document, whose reference-decided verdicts are not judged again (quality_claims.hpp).
  std::optional<ReferenceLadder> ladder;
};

// Fig. 7, the light occluded by the columns (DESIGN.md §11a.2, schema 7; quality --visibility ism
// or exact): the references with and without exact visibility, the occluded region O they fix,
// and each generator's frames shaded with that visibility, their error over O.
struct OcclusionMeasure {
  std::string visibility;  // how the generators' frames were shaded (shading_visibility_text)
  // R_v: every VPL of the RSM at this stride (of the RSM the reference's VPLs come from) traced to
  // every pixel; R_0 the same VPLs without visibility.
  uint32_t reference_rsm_stride = 0, reference_rsm_side = 0;
  uint64_t reference_vpls = 0;
  double reference_seconds = 0;  // shading R_v and its rungs
  uint64_t surface_pixels = 0, occluded_pixels = 0;
  double unshadowed_mean_luminance = 0;  // Y_0 bar over the pixels with a surface
  double occluded_light_share = 0;       // sum over O of (Y_0 - Y_v) / sum of Y_0 over the surface
  std::string region_rule;               // O, in words
  std::string note;                      // "" or why nothing is judged (no occluded region)
  // R_v's ladder in "relative_rmse" over O (the rungs against the next finer one).
  ReferenceLadder ladder;
  // Per generator "relative_rmse" over O per static frame against R_v, and against each coarser
  // rung (second_rung, coarse_rungs); gbuffer_stride and image are the comparison's.
  FrameErrors frames;
  // The control: the same VSGLs with exact visibility from their means, at the first
  // control_frames offsets, "relative_rmse" over O against R_v (reported, not judged).
  uint32_t control_frames = 0;
  std::map<std::string, std::vector<double>> control;
};

struct QualityModel {
  std::string schema = "vsgl-quality";
  nlohmann::ordered_json schema_version;
  std::string scene;
  std::string capture_path;
  nlohmann::ordered_json gbuffer_size, rsm_size;  // [w, h] and [side, side]
  nlohmann::ordered_json capture_hashes;          // provenance, raw
  std::string device_name, device_driver;
  BuildRecord build;  // the header every document shares (formats/run_header.hpp)
  std::vector<std::string> generators;
  nlohmann::ordered_json light_vsgls, camera_vsgls, K, frames;  // printed as written
  // The rest of "config" (iterations, strides, the sweep's K, definitions), raw; to_json writes
  // the typed configuration fields over it.
  nlohmann::ordered_json config_rest = nlohmann::ordered_json::object();
  std::map<std::string, ViewQuality> views;  // "camera_view", "light_view"
  nlohmann::ordered_json reference_vpls, reference_rsm_side, reference_rsm_stride,
      reference_image;  // printed as written
  // Which capture's RSM the reference's VPLs come from (schema 5, optional): {capture, path, rsm,
  // rsm_hashes}; null in documents written before it.
  nlohmann::ordered_json reference_vpl_source;
  double reference_power_ratio = 0;
  std::string reference_method;
  std::map<std::string, ImageErrorSummary> reference_error;
  std::optional<ReferenceDetail> reference_detail;                   // schema 4
  std::map<std::string, ImageErrorSummary> reference_error_support;  // schema 4: against the PDF-support reference
  nlohmann::ordered_json flicker_image;
  uint32_t flicker_gbuffer_stride = 0;
  std::map<std::string, StaticFlicker> flicker_static;
  struct Animated {
    nlohmann::ordered_json frames;
    std::string sequence, note, scene;
    std::vector<std::string> frame_content_hashes;
    uint32_t gbuffer_stride = 0, reference_rsm_stride = 0;
    double reference_weighted_cv = 0;
    std::map<std::string, AnimatedFlicker> generators;
  };
  std::optional<Animated> flicker_animated;
  std::optional<FrameErrors> frames_static, frames_animated;            // schema 5
  std::vector<std::pair<std::string, std::vector<KSweepRow>>> k_sweep;  // in the file's order
  std::optional<OcclusionMeasure> occlusion;                            // schema 7, with visibility
  // ClaimLayout::kQuality: the numbers each claim was judged on (fis_tok15, fis_modified, and a
  // claim's own, such as the Fig. 1 margin) are its `measured`. None before add_claim_verdicts,
  // and then not written.
  std::optional<std::vector<Claim>> claims;
  std::vector<std::pair<std::string, double>> timings_s;
};

// Throws InputError ("<what>: <pointer>: <problem>").
QualityModel quality_model_from_json(const nlohmann::ordered_json& doc, const std::string& what);

// The document of `m`: quality_model_from_json(to_json(m)) == m, field for field, and for a
// document the writer wrote, to_json(quality_model_from_json(doc)) == doc.
void to_json(nlohmann::ordered_json& j, const QualityModel& m);

}  // namespace vsgl
