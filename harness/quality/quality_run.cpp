#include "harness/quality/quality_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "harness/core/path_text.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/vk/buffer.hpp"
#include "harness/scene/capture_provisioning.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/core/error.hpp"
#include "harness/core/statistics.hpp"
#include "harness/core/generator_ids.hpp"
#include "harness/reference/fis_reference.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/quality/flip.hpp"
#include "harness/quality/flux_origin.hpp"
#include "harness/quality/frame_error.hpp"
#include "harness/quality/generator_run.hpp"
#include "harness/quality/occlusion_run.hpp"
#include "harness/quality/quality_metrics.hpp"
#include "harness/formats/quality_model.hpp"
#include "harness/quality/quality_pictures.hpp"
#include "harness/quality/quality_reference.hpp"
#include "harness/quality/reference_capture.hpp"
#include "harness/formats/run_header.hpp"
#include "harness/quality/shading_pass.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

// FIS VSGLs have kernel footprints (a level per kernel); coverage and the K sweep are about them.
bool is_fis(const std::string& name) { return generator_descriptor(name).family == GeneratorFamily::kFis; }

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// What the CPU keeps of one view: the PDF pyramid (M2's .w is q) and the total flux (M0).
struct ViewData {
  MipPyramid pdf;
  double flux = 0;
  std::vector<float> texel_flux;  // f per level-0 texel (flux_origin.hpp)
};

ViewData view_data(const Capture& capture, ViewKind kind) {
  const ViewImage& view = capture.view(kind);
  const glm::vec3 source = kind == ViewKind::kCamera ? capture.meta.camera.position : capture.meta.light.position;
  const auto moments = reference_moments(view, source);
  return ViewData{MipPyramid::build(moments[2], view.width, view.height), total_flux(moments[0]),
                  texel_flux(moments[0])};
}

double power_sum(const std::vector<VsglRecord>& vsgls) {
  double s = 0;
  for (const auto& v : vsgls) s += static_cast<double>(scalar_power(v));
  return s;
}

MassSummary summary_of(const SampleStats& s) { return {s.mean, s.stdev, s.min, s.max, s.p99}; }

PowerSummary power_summary(const PowerMetrics& p) {
  return {p.max_over_mean, p.p99_over_mean, p.power_ratio, p.total_vsgl_power, p.total_flux};
}

CoverageCountsSummary counts_summary(const CoverageCounts& c, std::optional<double> overlap = std::nullopt) {
  return {c.gap, c.surplus, c.count_error, c.mean_count, overlap};
}

// A generator's coverage on the view, its lattice floor (the same generator on the view's uniform
// copy) and the excess of the one over the other (DESIGN.md §11a).
CoverageSummary coverage_summary(const FootprintCoverage& f, const FootprintCoverage& floor) {
  const KernelCoverage& c = f.coverage;
  const CoverageExcess e = coverage_excess(f, floor);
  CoverageSummary s;
  s.gap = c.gap;
  s.overlap = c.overlap;
  s.gap_plus_overlap = c.gap + c.overlap;
  s.texels_with_pdf = c.texels_with_pdf;
  s.gap_texels = c.gap_texels;
  s.overlap_texels = c.overlap_texels;
  s.mass_over_target = summary_of(c.mass);
  s.box = counts_summary(f.box);
  s.eq3 = counts_summary(f.eq3);
  s.floor_box = counts_summary(floor.box, floor.coverage.overlap);
  s.floor_eq3 = counts_summary(floor.eq3);
  s.excess_box = counts_summary(e.box, e.box_overlap);
  s.excess_eq3 = counts_summary(e.eq3);
  return s;
}

PdfFrequencySummary frequency_summary(const PdfFrequency& f, uint32_t levels, uint32_t N, float K) {
  // The mean kernel side of the view, sqrt(K M / N) = 2^l_bar texels: details at levels below
  // floor(l_bar) vary inside a kernel, which is what a kernel sized from p(x_i) alone misjudges.
  const double l_bar = 0.5 * std::log2(static_cast<double>(K) * std::exp2(2.0 * levels) / static_cast<double>(N));
  const int k_kernel = std::clamp(static_cast<int>(std::floor(l_bar)) - 1, 0, static_cast<int>(levels) - 1);
  const int k_8 = std::min(2, static_cast<int>(levels) - 1);
  PdfFrequencySummary s;
  s.relative_variance = f.relative_variance;
  s.fine_share = f.fine_share;
  s.share_below_kernel = f.fine_share.empty() ? 0.0 : f.fine_share[static_cast<std::size_t>(k_kernel)];
  s.share_below_kernel_side_texels = std::exp2(k_kernel + 1);
  s.mean_kernel_side_texels = std::exp2(l_bar);
  s.detail_energy = f.detail_energy;
  s.mean_square = f.mean_square;
  s.share_below_8_texels = f.fine_share.empty() ? 0.0 : f.fine_share[static_cast<std::size_t>(k_8)];
  s.definition =
      "Haar wavelet spectrum on the PDF's mip levels: p = q / mean over the virtual square; "
      "detail_energy[l] = mean over the square of (p_bar_l - p_bar_(l+1))^2 (wavelengths ~2^(l+1) texels); "
      "mean_square = mean(p^2) = 1 + sum detail_energy; fine_share[k] = (detail_energy[0] + ... + "
      "detail_energy[k]) / mean_square, the share of the PDF's energy at wavelengths below 2^(k+1) texels "
      "(0: uniform, ~0.5: a texel checkerboard of 1 and 0)";
  return s;
}

FluxByPdfSummary flux_by_pdf_summary(const FluxByPdf& f) {
  FluxByPdfSummary s;
  s.bounds.assign(kExpectedCentreBounds.begin(), kExpectedCentreBounds.end());
  s.texels.assign(f.texels.begin(), f.texels.end());
  s.flux_share.assign(f.flux_share.begin(), f.flux_share.end());
  s.oversized_mass = kOversizedMass;
  s.definition =
      "texels with positive flux classed by their expected number of kernel centres e = N q / sum q: q = 0, "
      "e < bounds[0], ..., e >= bounds.back(); flux_share: the class's share of the view's flux. A FIS generator's "
      "flux_origin.gathered[c] = sum over class c of f(t) c(t) / flux, c(t) = sum_i M w_i(t) / D_i (w_i the "
      "trilinear weights of kernel i, D_i the density its power divides by), so the classes sum to sum Phi / flux; "
      "gathered_by_oversized: the same over the kernels whose mass a(l) p_bar N / K exceeds oversized_mass; "
      "pdf_weighted_count = sum q c / sum q (1 for Eq. 5)";
  return s;
}

FluxOriginSummary flux_origin_summary(const FluxOrigin& f) {
  return {std::vector<double>(f.gathered.begin(), f.gathered.end()),
          std::vector<double>(f.gathered_by_oversized.begin(), f.gathered_by_oversized.end()),
          f.attributed_power_ratio,
          f.pdf_weighted_count,
          f.oversized_kernels,
          std::nullopt};
}

FisVariant fis_variant(const std::string& name) {
  return name == kFisTok15 ? FisVariant::kTok15 : FisVariant::kModified;
}

// Mean and sample stdev over the frames of each class's gathered share and of sum Phi / flux.
FluxOriginFrames flux_origin_frames(const std::vector<FluxOrigin>& origins) {
  FluxOriginFrames out;
  out.frames = static_cast<uint32_t>(origins.size());
  for (std::size_t c = 0; c < kFluxClasses; ++c) {
    std::vector<double> v;
    for (const FluxOrigin& o : origins) v.push_back(o.gathered[c]);
    const SampleStats s = summarize(v);
    out.gathered_mean.push_back(s.mean);
    out.gathered_stdev.push_back(s.stdev);
  }
  std::vector<double> ratios, oversized;
  for (const FluxOrigin& o : origins) {
    ratios.push_back(o.attributed_power_ratio);
    double by_oversized = 0;
    for (double g : o.gathered_by_oversized) by_oversized += g;
    oversized.push_back(by_oversized / o.attributed_power_ratio);
  }
  const SampleStats r = summarize(ratios);
  out.ratio_mean = r.mean;
  out.ratio_stdev = r.stdev;
  out.ratio_min = r.min;
  out.ratio_max = r.max;
  out.oversized_share_mean = summarize(oversized).mean;
  return out;
}

ImageErrorSummary error_summary(const ImageError& e) { return {e.relative_rmse, e.p99_pixel_error}; }

// 64-bit FNV-1a over text: one identifier for all channel hashes of a capture.
std::string text_hash(const std::string& text) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[40];
  std::snprintf(buf, sizeof buf, "fnv1a64:%016llx", static_cast<unsigned long long>(h));
  return buf;
}

uint32_t stride_for_width(uint32_t width, uint32_t target) {
  return target == 0 || width <= target ? 1u : width / target;
}

std::string k_label(float K) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", static_cast<double>(K));
  return buf;
}

// Pictures at half the error resolution, to keep them small.
constexpr uint32_t kTileFactor = 2;

// The references (DESIGN.md §11a) every frame, the K sweep and the pictures compare with.
struct ReferenceShading {
  RadianceImage image;          // all lit texels
  RadianceImage support_image;  // the PDF's support
  float exposure = 1;           // of every render picture (a scale)
  FlipSettings flip;            // FLIP of every frame: the reference's exposure, in stops
  uint32_t error_stride = 1;    // the G-buffer stride of every comparison with it
  // The ladder's stride-2 rung, the same pixels: every frame is compared with it too, for the
  // rule's second verdict (DESIGN.md §11a *Rule*). None where the RSM has no such rung.
  std::optional<RadianceImage> second_rung;
  // The rungs coarser still, coarsest first, and their RSM strides (schema 7): the reference-decided
  // claims are computed against every rung (DESIGN.md §11a *Rule*).
  std::vector<RadianceImage> coarse_rungs;
  std::vector<uint32_t> coarse_rung_strides;
};

// The images the K sweep reuses from the static frames: each FIS generator's frame at offset 0.
using OffsetZeroImages = std::map<std::string, RadianceImage>;

// One generator's static frames (DESIGN.md §11a.1): the per-frame series, the flicker, the
// light-view flux origins (FIS), and the frames the pictures show.
struct StaticFrames {
  FrameSeries series;
  FrameSeries second_rung;  // the image errors against the stride-2 rung (schema 6)
  std::vector<FrameSeries> coarse_rungs;  // against each coarser rung (schema 7)
  FlickerAccumulator flicker;
  std::vector<FluxOrigin> origins;
  RadianceImage offset_zero, worst;
  std::size_t worst_frame = 0;
};

void add_image_error(FrameSeries& series, const FrameImageError& e) {
  series["rel_mse"].push_back(e.rel_mse);
  series["relative_rmse"].push_back(e.relative_rmse);
  series["scaled_rmse"].push_back(e.scaled_rmse);
  series["scale"].push_back(e.scale);
  series["flip"].push_back(e.flip);
  series["p99_pixel_error"].push_back(e.p99_pixel_error);
  series["max_pixel_error"].push_back(e.max_pixel_error);
}

// The metrics of the reference ladder (DESIGN.md §11a): the errors of frame_image_error, less the
// scale (it tends to 1, not 0) and the maximum pixel error (an extreme, no rate to expect).
constexpr const char* kLadderMetrics[] = {"rel_mse", "relative_rmse", "scaled_rmse", "flip", "p99_pixel_error"};

// One quality run: the device, the capture and its views on the device, and the lattice floor's
// input, the same views with the PDF 1 on the texels it weighs (DESIGN.md §11a). Each block of
// the report is one function, in the order run_quality calls them.
struct QualityRun {
  Device& device;
  const Capture& capture;
  const QualityConfig& config;
  const std::function<void(const std::string&)>& progress;
  const std::string scene;
  const DeviceView& camera;
  const DeviceView& light;
  const Capture& floor_capture;
  const DeviceView& floor_camera;
  const DeviceView& floor_light;
  const MipPyramid& floor_light_pdf;
  // Where the reference's VPLs come from: the capture's RSM, or a reference capture's larger one.
  const ViewImage& reference_rsm;

  void say(const std::string& line) const {
    if (progress) progress(line);
  }

  // Coverage of a generator's kernels on a view beside the same generator's, at the same lattice
  // offset, on the view's floor.
  CoverageSummary coverage_with_floor(const std::vector<VsglRecord>& kernels, const MipPyramid& pdf,
                                      const DeviceView& floor_view, const MipPyramid& floor_pdf,
                                      const std::string& name, uint32_t n, float K, uint32_t offset_bits = 0) const {
    const GeneratorRun floor_run = run_generator(device, floor_view, name, config, n, K, offset_bits);
    return coverage_summary(footprint_coverage(kernels, pdf, K), footprint_coverage(floor_run.vsgls, floor_pdf, K));
  }

  // 1-3: per view and generator: coverage (FIS), too-bright, power. Keeps the light view's PDF.
  void view_metrics(QualityModel& out, QualityResult& result, MipPyramid& light_pdf) const {
    for (ViewKind kind : {ViewKind::kLight, ViewKind::kCamera}) {
      const ViewData data = view_data(capture, kind);
      const DeviceView& view = kind == ViewKind::kLight ? light : camera;
      const DeviceView& floor_view = kind == ViewKind::kLight ? floor_light : floor_camera;
      const MipPyramid floor_pdf = kind == ViewKind::kLight ? floor_light_pdf : view_data(floor_capture, kind).pdf;
      const uint32_t n = kind == ViewKind::kLight ? config.light_vsgls : config.camera_vsgls;
      if (kind == ViewKind::kLight) light_pdf = data.pdf;
      ViewQuality v;
      v.vsgls = n;
      v.total_flux = data.flux;
      v.pdf_frequency = frequency_summary(pdf_frequency(data.pdf), data.pdf.levels(), n, config.K);
      v.flux_by_pdf = flux_by_pdf_summary(flux_by_pdf(data.texel_flux, data.pdf, n));
      for (const auto& name : config.generators) {
        const auto tg = Clock::now();
        const GeneratorRun run = run_generator(device, view, name, config, n, config.K, 0);
        GeneratorQuality g;
        g.power = power_summary(power_metrics(run.vsgls, data.flux));
        if (is_fis(name)) {
          g.coverage = coverage_with_floor(run.vsgls, data.pdf, floor_view, floor_pdf, name, n, config.K);
          g.flux_origin =
              flux_origin_summary(flux_origin(run.vsgls, fis_variant(name), data.texel_flux, data.pdf, config.K));
          const std::string file = scene + "_coverage_" + view_name(kind) + "_" + name + ".png";
          result.pictures.push_back(
              {file,
               "Fig. 1 analog, " + std::string(view_name(kind)) + ", " + name +
                   ": PDF in grey (sqrt scale), kernel centres red, footprints (side 2^l texels) orange",
               coverage_picture(data.pdf, run.vsgls, config.coverage_picture_side)});
        }
        v.generators[name] = g;
        say(std::string(view_name(kind)) + " " + name + ": metrics in " + std::to_string(seconds_since(tg)) + " s");
      }
      out.views[view_name(kind)] = v;
    }
  }

  // A reference VPL set shaded at `error_stride`, timed.
  struct ShadedReference {
    std::vector<VsglRecord> vpls;
    RadianceImage image;
    double seconds = 0;
  };
  ShadedReference shade_reference(uint32_t rsm_stride, VplSet set, uint32_t error_stride) const {
    const auto t0 = Clock::now();
    ShadedReference r;
    r.vpls = reference_vpls(reference_rsm, capture.meta.light, rsm_stride, VplExtent::kTexelFootprint, set);
    FixedVsglGenerator reference(device, r.vpls, std::string("reference_") + vpl_set_name(set));
    r.image = shade_camera_view(device, camera, reference.vsgls(), reference.vsgl_count(), error_stride);
    r.seconds = seconds_since(t0);
    return r;
  }

  // The VPL count of a set without building its records.
  uint64_t vpl_count(uint32_t rsm_stride, VplSet set) const {
    uint64_t n = 0;
    const ViewImage& rsm = reference_rsm;
    for (uint32_t y = 0; y < rsm.height; y += rsm_stride)
      for (uint32_t x = 0; x < rsm.width; x += rsm_stride) {
        if (rsm.at(kValid, x, y) <= 0.5f) continue;
        if (set == VplSet::kPdfSupport && !(rsm.at(kPdf, x, y) > 0.0f)) continue;
        const float f = rsm.at(kDR, x, y) + rsm.at(kDG, x, y) + rsm.at(kDB, x, y) + rsm.at(kSR, x, y) +
                        rsm.at(kSG, x, y) + rsm.at(kSB, x, y);
        if (f > 0.0f) ++n;
      }
    return n;
  }

  // The camera size (DESIGN.md §11a): the given stride, or by the budget: shade the coarsest set at
  // the reduced size and predict the whole reference work (every convergence stride, both
  // references) at full size from its rate. A probe shaded at the chosen size is kept in `coarse`.
  uint32_t camera_size(ReferenceDetail& detail, const std::vector<uint32_t>& strides, uint32_t ref_stride,
                       std::map<uint32_t, ShadedReference>& coarse) const {
    if (config.error_stride != 0) {
      detail.camera_size_rule = "G-buffer stride given (--error-stride)";
      return config.error_stride;
    }
    const uint32_t probe_stride = strides.empty() ? ref_stride : strides.front();
    ShadedReference probe = shade_reference(probe_stride, VplSet::kAllLit, kReducedErrorStride);
    const double probe_work = static_cast<double>(probe.vpls.size()) * static_cast<double>(probe.image.pixels.size());
    double vpls_total =
        static_cast<double>(vpl_count(ref_stride, VplSet::kAllLit) + vpl_count(ref_stride, VplSet::kPdfSupport));
    for (uint32_t s : strides) vpls_total += static_cast<double>(vpl_count(s, VplSet::kAllLit));
    const double full_pixels = static_cast<double>(capture.gbuffer.width) * capture.gbuffer.height;
    const double predicted = probe.seconds * vpls_total * full_pixels / std::max(probe_work, 1.0);
    detail.predicted_full_size_s = predicted;
    const uint32_t error_stride = predicted <= config.reference_budget_s ? 1u : kReducedErrorStride;
    detail.camera_size_rule =
        "full size (G-buffer stride 1) when the references are predicted to shade within "
        "budget_s, from the rate of the coarsest set shaded at stride " +
        std::to_string(kReducedErrorStride) + "; else stride " + std::to_string(kReducedErrorStride);
    if (error_stride == kReducedErrorStride && probe_stride != ref_stride) coarse[probe_stride] = std::move(probe);
    return error_stride;
  }

  // 6: the converged reference (DESIGN.md §11a), its convergence table and its own error in every
  // frame metric, and the PDF-support reference.
  ReferenceShading reference(QualityModel& out, double light_flux) const {
    const uint32_t ref_stride = reference_stride(reference_rsm, config.reference_rsm);
    const uint32_t rsm_side = std::max(reference_rsm.width, reference_rsm.height);
    // The coarser strides of the convergence table, coarsest first, each leaving at least 2 texels a side.
    std::vector<uint32_t> strides;
    for (uint32_t k : kConvergenceStrides)
      if (ref_stride * k * 2 <= rsm_side) strides.push_back(ref_stride * k);
    ReferenceDetail detail;
    detail.budget_s = config.reference_budget_s;
    detail.evaluations_per_dispatch = kShadeEvaluationsPerDispatch;
    std::map<uint32_t, ShadedReference> coarse;
    const uint32_t error_stride = camera_size(detail, strides, ref_stride, coarse);
    detail.error_stride = error_stride;
    out.config_rest["error_stride"] = error_stride;

    const ShadedReference all = shade_reference(ref_stride, VplSet::kAllLit, error_stride);
    const RadianceImage& ref_image = all.image;
    // FLIP of every frame at the reference's own exposure (DESIGN.md §11a.1), in stops.
    const FlipSettings flip{std::log2(static_cast<double>(auto_exposure(ref_image))), kFlipDefaultPixelsPerDegree};
    detail.vsgls_per_dispatch = shade_chunk_vsgls(ref_image.pixels.size());
    detail.seconds = all.seconds;
    say("reference: " + std::to_string(all.vpls.size()) + " VPLs at " + std::to_string(ref_image.width) + "x" +
        std::to_string(ref_image.height) + " in " + std::to_string(all.seconds) + " s");
    for (uint32_t s : strides) {
      if (coarse.count(s) == 0) coarse[s] = shade_reference(s, VplSet::kAllLit, error_stride);
      const ShadedReference& c = coarse.at(s);
      detail.convergence.push_back({s, c.vpls.size(), image_error(c.image, ref_image).relative_rmse, c.seconds});
      say("reference stride " + std::to_string(s) + ": " + std::to_string(c.seconds) + " s");
    }
    detail.convergence.push_back({ref_stride, all.vpls.size(), 0.0, all.seconds});
    detail.own_error =
        detail.convergence.size() >= 2 ? detail.convergence[detail.convergence.size() - 2].relative_rmse : 0.0;
    // The ladder (DESIGN.md §11a): each rung against the next finer one, the same pixels and FLIP
    // exposure; the last pair (stride 2 against the reference) is the reference's own error.
    std::vector<const RadianceImage*> rungs;
    ReferenceLadder ladder;
    for (uint32_t s : strides) {
      rungs.push_back(&coarse.at(s).image);
      ladder.rsm_strides.push_back(s);
    }
    rungs.push_back(&ref_image);
    ladder.rsm_strides.push_back(ref_stride);
    for (uint32_t s : ladder.rsm_strides) ladder.rsm_sides.push_back((rsm_side + s - 1) / s);
    for (const RadianceImage* image : rungs) ladder.mean_luminances.push_back(mean_surface_luminance(*image));
    FrameSeries differences;  // by metric, coarsest pair first
    for (std::size_t i = 0; i + 1 < rungs.size(); ++i)
      add_image_error(differences, frame_image_error(*rungs[i], *rungs[i + 1], flip));
    if (!differences.empty()) {
      for (const auto& [metric, values] : differences) detail.own_errors[metric] = values.back();
      for (const char* metric : kLadderMetrics)
        ladder.metrics[metric] = reference_ladder_metric(differences.at(metric));
    }
    const std::size_t pairs = rungs.size() - 1;
    ladder.note = std::to_string(rungs.size()) + " rungs, " + std::to_string(pairs) + " successive difference(s)" +
                  (pairs >= 3   ? ""
                   : pairs == 2 ? ": the RSM is too small for the stride-8 rung, so the rate is the one ratio"
                                : ": the RSM is too small for a rate, so no claim on the reference's error is decided");
    detail.ladder = std::move(ladder);
    ShadedReference support = shade_reference(ref_stride, VplSet::kPdfSupport, error_stride);
    detail.support_vpls = support.vpls.size();
    detail.support_power_ratio = power_sum(support.vpls) / light_flux;
    detail.support_seconds = support.seconds;
    detail.support_vs_all_lit = image_error(support.image, ref_image).relative_rmse;
    say("support reference: " + std::to_string(support.vpls.size()) + " VPLs in " + std::to_string(support.seconds) +
        " s");
    out.reference_detail = detail;

    const std::vector<VsglRecord>& vpls = all.vpls;
    out.reference_rsm_stride = ref_stride;
    out.reference_rsm_side = (reference_rsm.width + ref_stride - 1) / ref_stride;
    out.reference_vpls = vpls.size();
    out.reference_power_ratio = power_sum(vpls) / light_flux;
    out.reference_image = json::array({ref_image.width, ref_image.height});
    out.reference_method =
        "Every stride-th texel with positive flux of the RSM vpl_source names is a VSGL of its own moments "
        "(level 0), flux scaled by stride^2, sigma^2 = A / 12 with A the world area the texel stands for "
        "(bounds the 1/d^2 spikes of point VPLs); shaded at the "
        "generators' pixels (G-buffer stride) by the same shading pass, in chunked dispatches";
    const float exposure = auto_exposure(downscale(ref_image, kTileFactor));
    ReferenceShading shading{ref_image, std::move(support.image), exposure, flip, error_stride, std::nullopt, {}, {}};
    if (const auto it = coarse.find(2 * ref_stride); it != coarse.end()) {
      shading.second_rung = std::move(it->second.image);
      for (uint32_t s : strides)
        if (s != 2 * ref_stride) {
          shading.coarse_rungs.push_back(std::move(coarse.at(s).image));
          shading.coarse_rung_strides.push_back(s);
        }
    }
    return shading;
  }

  // The light-view VSGLs of `name` at lattice offset `offset_bits` and K, shading the camera view
  // at the reference's pixels.
  RadianceImage shade_frame(const GeneratorRun& run, const ReferenceShading& ref) const {
    return shade_camera_view(device, camera, run.generator->vsgls(), run.generator->vsgl_count(), ref.error_stride);
  }

  // Fig. 1 and Fig. 5 of one FIS frame on both views: the coverage excess over the floor at the
  // same offset, the spread of the kernel mass, the brightest VSGL (DESIGN.md §11a.1).
  void fis_frame_coverage(FrameSeries& series, const std::string& name, const GeneratorRun& light_run,
                          const MipPyramid& light_pdf, const ViewData& camera_data, const MipPyramid& floor_camera_pdf,
                          uint32_t offset) const {
    const CoverageSummary lc = coverage_with_floor(light_run.vsgls, light_pdf, floor_light, floor_light_pdf, name,
                                                   config.light_vsgls, config.K, offset);
    series["light_view_coverage_excess"].push_back(lc.excess_eq3.count_error);
    series["light_view_mass_stdev"].push_back(lc.mass_over_target.stdev);
    const GeneratorRun cam = run_generator(device, camera, name, config, config.camera_vsgls, config.K, offset);
    const CoverageSummary cc = coverage_with_floor(cam.vsgls, camera_data.pdf, floor_camera, floor_camera_pdf, name,
                                                   config.camera_vsgls, config.K, offset);
    series["camera_view_coverage_excess"].push_back(cc.excess_eq3.count_error);
    series["camera_view_mass_stdev"].push_back(cc.mass_over_target.stdev);
    series["camera_view_max_over_mean"].push_back(power_metrics(cam.vsgls, camera_data.flux).max_over_mean);
  }

  // One generator over the static frames: every lattice offset's image error, flicker and, for
  // FIS, coverage and flux origin.
  StaticFrames frames_of(const std::string& name, const ReferenceShading& ref, const MipPyramid& light_pdf,
                         double light_flux, const ViewData& camera_data, const MipPyramid& floor_camera_pdf) const {
    const std::vector<float> light_texel_flux = view_data(capture, ViewKind::kLight).texel_flux;
    StaticFrames s;
    double worst = -1;
    for (uint32_t f = 0; f < config.frames; ++f) {
      const uint32_t offset = frame_offset_bits(f);
      const GeneratorRun run = run_generator(device, light, name, config, config.light_vsgls, config.K, offset);
      RadianceImage img = shade_frame(run, ref);
      s.flicker.add_frame(img, power_sum(run.vsgls));
      const FrameImageError e = frame_image_error(img, ref.image, ref.flip);
      add_image_error(s.series, e);
      if (ref.second_rung) add_image_error(s.second_rung, frame_image_error(img, *ref.second_rung, ref.flip));
      s.coarse_rungs.resize(ref.coarse_rungs.size());
      for (std::size_t r = 0; r < ref.coarse_rungs.size(); ++r)
        add_image_error(s.coarse_rungs[r], frame_image_error(img, ref.coarse_rungs[r], ref.flip));
      s.series["light_view_max_over_mean"].push_back(power_metrics(run.vsgls, light_flux).max_over_mean);
      if (is_fis(name)) {
        s.origins.push_back(flux_origin(run.vsgls, fis_variant(name), light_texel_flux, light_pdf, config.K));
        fis_frame_coverage(s.series, name, run, light_pdf, camera_data, floor_camera_pdf, offset);
      }
      if (e.relative_rmse > worst) {
        worst = e.relative_rmse;
        s.worst = img;
        s.worst_frame = f;
      }
      if (f == 0) s.offset_zero = std::move(img);
    }
    s.series["flicker_deviation"] = s.flicker.frame_deviations();
    return s;
  }

  // 4: the static frames (DESIGN.md §11a.1): every generator at each of the F lattice offsets,
  // its image error against the reference, flicker, and (FIS) coverage on both views; the renders
  // at offset 0 and each generator's worst frame as pictures.
  OffsetZeroImages static_frames(QualityModel& out, QualityResult& result, const ReferenceShading& ref,
                                 const MipPyramid& light_pdf, double light_flux) const {
    const ViewData camera_data = view_data(capture, ViewKind::kCamera);
    const MipPyramid floor_camera_pdf = view_data(floor_capture, ViewKind::kCamera).pdf;
    FrameErrors frames;
    frames.gbuffer_stride = ref.error_stride;
    frames.image = json::array({ref.image.width, ref.image.height});
    frames.reference = "the all-lit reference (every lit RSM texel a VPL), the same for every frame";
    frames.flip_exposure = ref.flip.exposure;
    frames.flip_pixels_per_degree = ref.flip.pixels_per_degree;
    if (ref.second_rung)
      frames.second_rung_reference =
          "the reference's stride-2 rung (every second texel of its RSM in x and y a VPL, flux x 4), the same pixels "
          "and FLIP exposure";
    frames.coarse_rung_strides = ref.coarse_rung_strides;
    const RadianceImage ref_tile = downscale(ref.image, kTileFactor);
    std::vector<Rgb8Image> render_tiles{tone_map(ref_tile, ref.exposure)},
        error_tiles{error_map(ref_tile, ref_tile, 1.0f)};
    std::vector<Rgb8Image> worst_tiles, worst_error_tiles;
    std::string worst_text;
    OffsetZeroImages offset_zero;
    for (const auto& name : config.generators) {
      const auto tg = Clock::now();
      StaticFrames s = frames_of(name, ref, light_pdf, light_flux, camera_data, floor_camera_pdf);
      out.flicker_static[name] = {s.flicker.weighted_cv(), s.flicker.power_stdev(), s.flicker.power_relative_stdev(),
                                  s.flicker.frames()};
      out.reference_error[name] = error_summary(image_error(s.offset_zero, ref.image));
      out.reference_error_support[name] = error_summary(image_error(s.offset_zero, ref.support_image));
      auto& light_view = out.views.at(view_name(ViewKind::kLight));
      if (!s.origins.empty() && light_view.generators.at(name).flux_origin)
        light_view.generators.at(name).flux_origin->over_frames = flux_origin_frames(s.origins);
      const RadianceImage tile = downscale(s.offset_zero, kTileFactor), worst = downscale(s.worst, kTileFactor);
      render_tiles.push_back(tone_map(tile, ref.exposure));
      error_tiles.push_back(error_map(tile, ref_tile, 1.0f));
      worst_tiles.push_back(tone_map(worst, ref.exposure));
      worst_error_tiles.push_back(error_map(worst, ref_tile, 1.0f));
      worst_text += (worst_text.empty() ? "" : ", ") + name + " frame " + std::to_string(s.worst_frame);
      frames.generators[name] = std::move(s.series);
      if (!s.second_rung.empty()) frames.second_rung[name] = std::move(s.second_rung);
      if (!s.coarse_rungs.empty()) frames.coarse_rungs[name] = std::move(s.coarse_rungs);
      if (is_fis(name)) offset_zero[name] = std::move(s.offset_zero);
      say("static frames " + name + ": " + std::to_string(seconds_since(tg)) + " s");
    }
    out.frames_static = std::move(frames);
    out.flicker_image = out.frames_static->image;
    out.flicker_gbuffer_stride = ref.error_stride;
    std::string order = "reference";
    for (const auto& g : config.generators) order += ", " + g;
    const auto grid = [](std::vector<Rgb8Image> top, const std::vector<Rgb8Image>& bottom) {
      const auto columns = static_cast<uint32_t>(top.size());
      top.insert(top.end(), bottom.begin(), bottom.end());
      return tile_grid(top, columns);
    };
    const std::string error_row = "|dY| / mean Y of the reference (black 0, red, yellow, white >= 1)";
    result.pictures.push_back({scene + "_renders.png",
                               "Fig. 5 analog at lattice offset 0. Top row: " + order +
                                   " (indirect light, no visibility, one exposure). Bottom row: " + error_row,
                               grid(render_tiles, error_tiles)});
    result.pictures.push_back({scene + "_worst_frames.png",
                               "Each generator's frame of largest relative RMSE (" + worst_text +
                                   "), same exposure as the renders. Bottom row: " + error_row,
                               grid(worst_tiles, worst_error_tiles)});
    return offset_zero;
  }

  // 5: the K sweep (Fig. 6) for the FIS generators: per K the static frames' flicker and error
  // (DESIGN.md §11a.1), and coverage and power at offset 0.
  void k_sweep(QualityModel& out, QualityResult& result, const ReferenceShading& ref,
               const OffsetZeroImages& offset_zero, const MipPyramid& light_pdf, double light_flux) const {
    std::vector<Rgb8Image> k_tiles;
    for (const auto& name : config.generators) {
      if (!is_fis(name)) continue;
      std::vector<KSweepRow> rows;
      for (float K : config.k_sweep) {
        const auto tg = Clock::now();
        KSweepRow row;
        row.K = K;
        RadianceImage img;
        if (K == config.K) {
          const StaticFlicker& f = out.flicker_static.at(name);
          row.weighted_cv = f.weighted_cv;
          row.power_stdev = f.power_stdev;
          row.power_relative_stdev = f.power_relative_stdev;
          row.frames = f.frames;
          const FrameSeries& series = out.frames_static->generators.at(name);
          row.per_frame = {{"flicker_deviation", series.at("flicker_deviation")},
                           {"relative_rmse", series.at("relative_rmse")}};
          if (const auto second = out.frames_static->second_rung.find(name);
              second != out.frames_static->second_rung.end())
            row.per_frame_second_rung = {{"relative_rmse", second->second.at("relative_rmse")}};
          if (const auto coarse = out.frames_static->coarse_rungs.find(name);
              coarse != out.frames_static->coarse_rungs.end())
            for (const FrameSeries& rung : coarse->second)
              row.per_frame_coarse_rungs.push_back({{"relative_rmse", rung.at("relative_rmse")}});
          img = offset_zero.at(name);
        } else {
          FlickerAccumulator acc;
          std::vector<double> error, error_second;
          std::vector<std::vector<double>> error_coarse(ref.coarse_rungs.size());
          for (uint32_t f = 0; f < config.frames; ++f) {
            const GeneratorRun run =
                run_generator(device, light, name, config, config.light_vsgls, K, frame_offset_bits(f));
            RadianceImage frame = shade_frame(run, ref);
            acc.add_frame(frame, power_sum(run.vsgls));
            error.push_back(image_error(frame, ref.image).relative_rmse);
            if (ref.second_rung) error_second.push_back(image_error(frame, *ref.second_rung).relative_rmse);
            for (std::size_t r = 0; r < ref.coarse_rungs.size(); ++r)
              error_coarse[r].push_back(image_error(frame, ref.coarse_rungs[r]).relative_rmse);
            if (f == 0) img = std::move(frame);
          }
          row.weighted_cv = acc.weighted_cv();
          row.power_stdev = acc.power_stdev();
          row.power_relative_stdev = acc.power_relative_stdev();
          row.frames = acc.frames();
          row.per_frame = {{"flicker_deviation", acc.frame_deviations()}, {"relative_rmse", std::move(error)}};
          if (!error_second.empty()) row.per_frame_second_rung = {{"relative_rmse", std::move(error_second)}};
          for (std::vector<double>& e : error_coarse)
            row.per_frame_coarse_rungs.push_back({{"relative_rmse", std::move(e)}});
        }
        const GeneratorRun run = run_generator(device, light, name, config, config.light_vsgls, K, 0);
        row.error = error_summary(image_error(img, ref.image));
        row.coverage = coverage_with_floor(run.vsgls, light_pdf, floor_light, floor_light_pdf, name, config.light_vsgls, K);
        row.power = power_summary(power_metrics(run.vsgls, light_flux));
        rows.push_back(row);
        k_tiles.push_back(tone_map(downscale(img, kTileFactor), ref.exposure));
        say("K sweep " + name + " K=" + k_label(K) + ": " + std::to_string(seconds_since(tg)) + " s");
      }
      out.k_sweep.emplace_back(name, std::move(rows));
    }
    if (!k_tiles.empty()) {
      std::string ks_text;
      for (float K : config.k_sweep) ks_text += (ks_text.empty() ? "" : ", ") + k_label(K);
      result.pictures.push_back({scene + "_k_sweep.png",
                                 "Fig. 6 analog: one row per FIS generator (" + std::string(kFisTok15) + ", then " +
                                     std::string(kFisModified) + "), K = " + ks_text +
                                     " left to right, same exposure as the renders",
                                 tile_grid(k_tiles, static_cast<uint32_t>(config.k_sweep.size()))});
    }
  }

  // 4b: the animated sequence (moving light and camera), reported separately: flicker, and every
  // frame's image error against its own reference (DESIGN.md §11a.1).
  void animated_sequence(QualityModel& out) const {
    const auto t0 = Clock::now();
    const auto frames = sequence_frames(*config.sequence, config.frames);
    std::map<std::string, FlickerAccumulator> acc;
    std::map<std::string, FrameSeries> series;
    FlickerAccumulator ref_acc;
    std::vector<std::string> hashes;
    uint32_t seq_stride = 1, seq_ref_stride = 1;
    std::string seq_scene;
    std::optional<FlipSettings> flip;
    json image;
    for (const auto& dir : frames) {
      const Capture c = load_capture(dir);
      if (seq_scene.empty()) seq_scene = c.meta.scene;
      hashes.push_back(text_hash(capture_hashes_json(c).dump()));
      const DeviceView cam = upload_view(device, c, ViewKind::kCamera);
      const DeviceView lig = upload_view(device, c, ViewKind::kLight);
      seq_stride = stride_for_width(c.gbuffer.width, config.flicker_width);
      seq_ref_stride = reference_stride(c.rsm, config.sequence_reference_rsm);
      FixedVsglGenerator ref(device, reference_vpls(c.rsm, c.meta.light, seq_ref_stride, VplExtent::kTexelFootprint), "sequence_reference");
      const RadianceImage ref_img = shade_camera_view(device, cam, ref.vsgls(), ref.vsgl_count(), seq_stride);
      // One exposure for the whole sequence: the first frame's reference's.
      if (!flip)
        flip = FlipSettings{std::log2(static_cast<double>(auto_exposure(ref_img))), kFlipDefaultPixelsPerDegree};
      image = json::array({ref_img.width, ref_img.height});
      ref_acc.add_frame(ref_img, 0.0);
      for (const auto& name : config.generators) {
        const GeneratorRun run = run_generator(device, lig, name, config, config.light_vsgls, config.K, 0);
        const RadianceImage img =
            shade_camera_view(device, cam, run.generator->vsgls(), run.generator->vsgl_count(), seq_stride);
        acc[name].add_frame(img, power_sum(run.vsgls), ref_img);
        add_image_error(series[name], frame_image_error(img, ref_img, *flip));
      }
    }
    QualityModel::Animated animated;
    FrameErrors errors;
    for (const auto& name : config.generators) {
      animated.generators[name] = {acc[name].weighted_cv(), acc[name].error_cv(), acc[name].power_relative_stdev()};
      series[name]["flicker_deviation"] = acc[name].frame_deviations();
      series[name]["error_flicker_deviation"] = acc[name].error_frame_deviations();
      errors.generators[name] = std::move(series[name]);
    }
    animated.sequence = config.sequence->string();
    animated.scene = seq_scene;
    animated.frames = frames.size();
    animated.frame_content_hashes = std::move(hashes);
    animated.gbuffer_stride = seq_stride;
    animated.reference_rsm_stride = seq_ref_stride;
    animated.reference_weighted_cv = ref_acc.weighted_cv();
    animated.note = "light and camera move: weighted_cv includes the true change (compare with the reference's); "
                      "error_cv = sum_p stdev_t(Y - Yref) / sum_p mean_t(Yref) is the change the reference does not have";
    errors.gbuffer_stride = seq_stride;
    errors.image = image;
    errors.reference = "each frame's own reference (every " + std::to_string(seq_ref_stride) +
                       "th RSM texel a VPL), convergence not measured";
    errors.flip_exposure = flip->exposure;
    errors.flip_pixels_per_degree = flip->pixels_per_degree;
    out.flicker_animated = std::move(animated);
    out.frames_animated = std::move(errors);
    say("animated sequence: " + std::to_string(frames.size()) + " frames in " + std::to_string(seconds_since(t0)) +
        " s");
  }
};

// Refuses a configuration that cannot run, before any work.
void check_config(const QualityConfig& config) {
  if (config.frames < 2) throw InputError("quality: --frames must be at least 2 (flicker compares frames)");
  if (!(config.reference_budget_s > 0.0)) throw InputError("quality: the reference's time budget must be positive");
  if (config.generators.empty()) throw InputError("quality: no generators");
  for (float K : config.k_sweep)
    if (!(K > 0.0f) || !std::isfinite(K)) throw InputError("quality: every K of the sweep must be positive");
  for (const auto& g : config.generators) (void)generator_sources(g);  // unknown names fail here, before any work
  if (config.visibility.mode != ShadingVisibility::kNone && config.control_frames > config.frames)
    throw InputError("quality: --control-frames (" + std::to_string(config.control_frames) +
                     ") is more than --frames (" + std::to_string(config.frames) + ")");
}

// What was measured: the schema, the capture with its hashes, the device, the build, the configuration.
void write_header(QualityModel& out, Device& device, const Capture& capture, const std::filesystem::path& capture_dir,
                  const QualityConfig& config) {
  out.schema = "vsgl-quality";
  out.schema_version = kQualitySchemaVersion;
  out.scene = capture.meta.scene;
  out.capture_path = capture_dir.string();
  out.gbuffer_size = json::array({capture.gbuffer.width, capture.gbuffer.height});
  out.rsm_size = json::array({capture.rsm.width, capture.rsm.height});
  out.capture_hashes = capture_hashes_json(capture);
  // The quality document's device: the name and the driver of the header's.
  const DeviceRecord header_device = device_record(device.info());
  out.device_name = header_device.name;
  out.device_driver = header_device.driver_name + " " + header_device.driver_info;
  out.build = this_build();
  out.generators = config.generators;
  out.light_vsgls = config.light_vsgls;
  out.camera_vsgls = config.camera_vsgls;
  out.K = config.K;
  out.frames = config.frames;
  std::vector<double> ks(config.k_sweep.begin(), config.k_sweep.end());
  out.config_rest = json{{"bisection_iterations", config.bisection_iterations},
                         {"kmeans_iterations", config.kmeans_iterations},
                         {"frame_offsets", "offset_bits(f) = bit-reversed f (van der Corput), f = 0..F-1"},
                         {"error_stride", config.error_stride},
                         {"flicker_width", config.flicker_width},
                         {"reference_rsm", config.reference_rsm},
                         {"sequence_reference_rsm", config.sequence_reference_rsm},
                         {"k_sweep", ks},
                         {"power_of_a_vsgl", "Phi.r + Phi.g + Phi.b"},
                         {"shading",
                          {{"model", std::string(kShadingModel)},
                           {"bias_reduction_alpha", double{gpu::kBiasReductionAlpha}},
                           {"text", shading_model_text()}}},
                         {"luminance", "Rec. 709"},
                         {"visibility", shading_visibility_name(config.visibility.mode)}};
  if (config.visibility.mode != ShadingVisibility::kNone) {
    out.config_rest["visibility_reference_rsm"] = config.visibility_reference_rsm;
    out.config_rest["control_frames"] = config.control_frames;
  }
}

}  // namespace

std::vector<std::filesystem::path> sequence_frames(const std::filesystem::path& dir, uint32_t max_frames) {
  std::vector<std::filesystem::path> frames;
  for (uint32_t f = 0; f < max_frames; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04u", f);
    const auto p = dir / name;
    if (!std::filesystem::exists(p / "capture.json")) break;
    frames.push_back(p);
  }
  if (frames.size() < 2)
    throw InputError(path_text(dir) +
                     ": not a recorded sequence (need frame_0000, frame_0001, ... with capture.json; "
                     "record one with `vsgl-bench record --frames F --out DIR`)");
  return frames;
}

QualityResult run_quality(Device& device, const Capture& capture, const std::filesystem::path& capture_dir,
                          const QualityConfig& config, const std::function<void(const std::string&)>& progress) {
  check_config(config);
  const auto t_start = Clock::now();
  QualityResult result;
  QualityModel out;
  write_header(out, device, capture, capture_dir, config);
  // Fig. 7's geometry (DESIGN.md §11a.2): a capture without it is refused here, naming the option of
  // `record` that stores it and --visibility none, before anything runs.
  std::optional<VisibilityGeometry> geometry;
  if (config.visibility.mode != ShadingVisibility::kNone)
    geometry = load_visibility_geometry(capture_dir, capture.meta);
  if (config.visibility.mode == ShadingVisibility::kIsm)  // the maps' settings against the capture and device
    VisibleShading(device, config.visibility, &*geometry).require_maps_fit(config.light_vsgls);

  const DeviceView camera = upload_view(device, capture, ViewKind::kCamera);
  const DeviceView light = upload_view(device, capture, ViewKind::kLight);
  // The lattice floor's input: the same views with the PDF 1 on the texels it weighs (DESIGN.md §11a).
  const Capture floor_capture{capture.meta, uniform_pdf_view(capture.gbuffer), uniform_pdf_view(capture.rsm)};
  const DeviceView floor_camera = upload_view(device, floor_capture, ViewKind::kCamera);
  const DeviceView floor_light = upload_view(device, floor_capture, ViewKind::kLight);
  const MipPyramid floor_light_pdf = view_data(floor_capture, ViewKind::kLight).pdf;
  // The reference's VPLs (DESIGN.md §11a): a reference capture's larger RSM when one is given.
  std::optional<Capture> reference_capture;
  if (config.reference_capture) {
    reference_capture = load_capture(*config.reference_capture);
    check_reference_capture(capture, *reference_capture, path_text(*config.reference_capture));
  }
  const Capture& vpl_capture = reference_capture ? *reference_capture : capture;
  out.reference_vpl_source = json{{"capture", reference_capture ? "reference capture" : "the capture itself"},
                                  {"path", path_text(reference_capture ? *config.reference_capture : capture_dir)},
                                  {"rsm", json::array({vpl_capture.rsm.width, vpl_capture.rsm.height})},
                                  {"rsm_hashes", capture_hashes_json(vpl_capture).at("rsm")}};
  const QualityRun run{device, capture,       config,       progress,    capture.meta.scene, camera,
                       light,  floor_capture, floor_camera, floor_light, floor_light_pdf,    vpl_capture.rsm};

  MipPyramid light_pdf;
  auto t0 = Clock::now();
  run.view_metrics(out, result, light_pdf);
  out.timings_s.emplace_back("view_metrics", seconds_since(t0));

  t0 = Clock::now();
  const double light_flux = out.views.at("light_view").total_flux;
  const ReferenceShading reference = run.reference(out, light_flux);
  out.timings_s.emplace_back("reference", seconds_since(t0));

  t0 = Clock::now();
  const OffsetZeroImages offset_zero = run.static_frames(out, result, reference, light_pdf, light_flux);
  out.timings_s.emplace_back("static_frames", seconds_since(t0));

  t0 = Clock::now();
  run.k_sweep(out, result, reference, offset_zero, light_pdf, light_flux);
  out.timings_s.emplace_back("k_sweep", seconds_since(t0));

  if (config.sequence) {
    t0 = Clock::now();
    run.animated_sequence(out);
    out.timings_s.emplace_back("animated_sequence", seconds_since(t0));
  }
  if (geometry) {
    t0 = Clock::now();
    OcclusionResult occlusion =
        measure_occlusion({device, capture, config, camera, light, vpl_capture.rsm, reference.error_stride, *geometry,
                           [&progress](const std::string& line) {
                             if (progress) progress(line);
                           }});
    out.occlusion = std::move(occlusion.measure);
    for (QualityPicture& p : occlusion.pictures) result.pictures.push_back(std::move(p));
    out.timings_s.emplace_back("occlusion", seconds_since(t0));
  }
  out.timings_s.emplace_back("total", seconds_since(t_start));
  result.json = out;
  return result;
}

}  // namespace vsgl
