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
#include "harness/core/generator_ids.hpp"
#include "harness/reference/fis_reference.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/quality/flux_origin.hpp"
#include "harness/quality/quality_metrics.hpp"
#include "harness/formats/quality_model.hpp"
#include "harness/quality/quality_pictures.hpp"
#include "harness/quality/quality_reference.hpp"
#include "harness/timing/run_provenance.hpp"
#include "harness/quality/shading_pass.hpp"

namespace vsgl {
namespace {

using nlohmann::json;
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

// One generator run (offset `offset_bits`, kernel parameter K) on an uploaded view; its VSGLs stay
// on the device for shading and are downloaded for the metrics.
struct GeneratorRun {
  std::unique_ptr<VsglGenerator> generator;
  std::vector<VsglRecord> vsgls;
};

GeneratorRun run_generator(Device& device, const DeviceView& view, const std::string& name,
                           const QualityConfig& config, uint32_t vsgl_count, float K, uint32_t offset_bits) {
  GeneratorConfig gc;
  gc.vsgl_count = vsgl_count;
  gc.K = K;
  gc.bisection_iterations = config.bisection_iterations;
  gc.kmeans_iterations = config.kmeans_iterations;
  gc.offset_bits = offset_bits;
  gc.pyramid = config.pyramid;
  gc.mipmapping = config.mipmapping;
  GeneratorRun run;
  run.generator = make_generator(name, device, view, gc);
  run_untimed(device, *run.generator);
  run.vsgls = download_vector<VsglRecord>(device, run.generator->vsgls(), run.generator->vsgl_count());
  return run;
}

double power_sum(const std::vector<VsglRecord>& vsgls) {
  double s = 0;
  for (const auto& v : vsgls) s += static_cast<double>(scalar_power(v));
  return s;
}

MassSummary summary_of(const ValueSummary& s) { return {s.mean, s.stdev, s.min, s.max, s.p99}; }

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
    const ValueSummary s = summarize_values(v);
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
  const ValueSummary r = summarize_values(ratios);
  out.ratio_mean = r.mean;
  out.ratio_stdev = r.stdev;
  out.ratio_min = r.min;
  out.ratio_max = r.max;
  out.oversized_share_mean = summarize_values(oversized).mean;
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

// The reference image (DESIGN.md §11) the errors, the K sweep and the pictures compare with.
struct ReferenceShading {
  RadianceImage image;
  float exposure;                                  // of every render picture
  std::map<std::string, RadianceImage> k1_images;  // the FIS generators' renders at the configured K
  uint32_t error_stride = 1;                       // the G-buffer stride of every comparison with it
};

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

  void say(const std::string& line) const {
    if (progress) progress(line);
  }

  // Coverage of a generator's kernels on a view beside the same generator's on the view's floor.
  CoverageSummary coverage_with_floor(const std::vector<VsglRecord>& kernels, const MipPyramid& pdf, const DeviceView& floor_view,
                           const MipPyramid& floor_pdf, const std::string& name, uint32_t n, float K) const {
    const GeneratorRun floor_run = run_generator(device, floor_view, name, config, n, K, 0);
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
    r.vpls = reference_vpls(capture.rsm, capture.meta.light, rsm_stride, VplExtent::kTexelFootprint, set);
    FixedVsglGenerator reference(device, r.vpls, std::string("reference_") + vpl_set_name(set));
    r.image = shade_camera_view(device, camera, reference.vsgls(), reference.vsgl_count(), error_stride);
    r.seconds = seconds_since(t0);
    return r;
  }

  // The VPL count of a set without building its records.
  uint64_t vpl_count(uint32_t rsm_stride, VplSet set) const {
    uint64_t n = 0;
    const ViewImage& rsm = capture.rsm;
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

  // 6: the converged reference (DESIGN.md §11a) and the errors against it (light-view VSGLs shading
  // the camera view).
  ReferenceShading reference_and_errors(QualityModel& out, QualityResult& result, double light_flux) const {
    const uint32_t ref_stride = reference_stride(capture.rsm, config.reference_rsm);
    const uint32_t rsm_side = std::max(capture.rsm.width, capture.rsm.height);
    // The coarser strides of the convergence table, coarsest first, each leaving at least 2 texels a side.
    std::vector<uint32_t> strides;
    for (uint32_t k : kConvergenceStrides)
      if (ref_stride * k * 2 <= rsm_side) strides.push_back(ref_stride * k);
    ReferenceDetail detail;
    detail.budget_s = config.reference_budget_s;
    detail.evaluations_per_dispatch = kShadeEvaluationsPerDispatch;
    std::map<uint32_t, ShadedReference> coarse;
    uint32_t error_stride = config.error_stride;
    if (error_stride == 0) {
      // Camera size by the budget: shade the coarsest set at the reduced size, and predict the
      // whole reference work (every convergence stride, both references) at full size from its rate.
      const uint32_t probe_stride = strides.empty() ? ref_stride : strides.front();
      ShadedReference probe = shade_reference(probe_stride, VplSet::kAllLit, kReducedErrorStride);
      const double probe_work = static_cast<double>(probe.vpls.size()) * static_cast<double>(probe.image.pixels.size());
      double vpls_total =
          static_cast<double>(vpl_count(ref_stride, VplSet::kAllLit) + vpl_count(ref_stride, VplSet::kPdfSupport));
      for (uint32_t s : strides) vpls_total += static_cast<double>(vpl_count(s, VplSet::kAllLit));
      const double full_pixels = static_cast<double>(capture.gbuffer.width) * capture.gbuffer.height;
      const double predicted = probe.seconds * vpls_total * full_pixels / std::max(probe_work, 1.0);
      detail.predicted_full_size_s = predicted;
      error_stride = predicted <= config.reference_budget_s ? 1u : kReducedErrorStride;
      detail.camera_size_rule =
          "full size (G-buffer stride 1) when the references are predicted to shade within "
          "budget_s, from the rate of the coarsest set shaded at stride " +
          std::to_string(kReducedErrorStride) + "; else stride " + std::to_string(kReducedErrorStride);
      if (error_stride == kReducedErrorStride && probe_stride != ref_stride) coarse[probe_stride] = std::move(probe);
    } else {
      detail.camera_size_rule = "G-buffer stride given (--error-stride)";
    }
    detail.error_stride = error_stride;
    out.config_rest["error_stride"] = error_stride;

    const ShadedReference all = shade_reference(ref_stride, VplSet::kAllLit, error_stride);
    const RadianceImage& ref_image = all.image;
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
    const ShadedReference support = shade_reference(ref_stride, VplSet::kPdfSupport, error_stride);
    detail.support_vpls = support.vpls.size();
    detail.support_power_ratio = power_sum(support.vpls) / light_flux;
    detail.support_seconds = support.seconds;
    detail.support_vs_all_lit = image_error(support.image, ref_image).relative_rmse;
    say("support reference: " + std::to_string(support.vpls.size()) + " VPLs in " + std::to_string(support.seconds) +
        " s");
    out.reference_detail = detail;

    const std::vector<VsglRecord>& vpls = all.vpls;
    out.reference_rsm_stride = ref_stride;
    out.reference_rsm_side = (capture.rsm.width + ref_stride - 1) / ref_stride;
    out.reference_vpls = vpls.size();
    out.reference_power_ratio = power_sum(vpls) / light_flux;
    out.reference_image = json::array({ref_image.width, ref_image.height});
    out.reference_method =
        "Every stride-th RSM texel with positive flux is a VSGL of its own moments "
        "(level 0), flux scaled by stride^2, sigma^2 = A / 12 with A the world area the texel stands for "
        "(bounds the 1/d^2 spikes of point VPLs); shaded at the "
        "generators' pixels (G-buffer stride) by the same shading pass, in chunked dispatches";
    const float exposure = auto_exposure(downscale(ref_image, kTileFactor));
    std::vector<Rgb8Image> render_tiles{tone_map(downscale(ref_image, kTileFactor), exposure)};
    std::vector<Rgb8Image> error_tiles{error_map(downscale(ref_image, kTileFactor), downscale(ref_image, kTileFactor), 1.0f)};
    std::map<std::string, RadianceImage> k1_images;
    for (const auto& name : config.generators) {
      const GeneratorRun run = run_generator(device, light, name, config, config.light_vsgls, config.K, 0);
      const RadianceImage img =
          shade_camera_view(device, camera, run.generator->vsgls(), run.generator->vsgl_count(), error_stride);
      out.reference_error[name] = error_summary(image_error(img, ref_image));
      out.reference_error_support[name] = error_summary(image_error(img, support.image));
      render_tiles.push_back(tone_map(downscale(img, kTileFactor), exposure));
      error_tiles.push_back(error_map(downscale(img, kTileFactor), downscale(ref_image, kTileFactor), 1.0f));
      if (is_fis(name)) k1_images[name] = img;
    }
    {
      std::vector<Rgb8Image> tiles = render_tiles;
      tiles.insert(tiles.end(), error_tiles.begin(), error_tiles.end());
      std::string order = "reference";
      for (const auto& g : config.generators) order += ", " + g;
      result.pictures.push_back({scene + "_renders.png",
                                 "Fig. 5 analog. Top row: " + order +
                                     " (indirect light, no visibility, one exposure). Bottom row: |dY| / mean Y of the "
                                     "reference (black 0, red, yellow, white >= 1)",
                                 tile_grid(tiles, static_cast<uint32_t>(render_tiles.size()))});
    }
    return ReferenceShading{ref_image, exposure, k1_images, error_stride};
  }

  // 4 + 5: static flicker over offsets, with the K sweep for the FIS generators.
  void flicker_and_k_sweep(QualityModel& out, QualityResult& result, const ReferenceShading& reference,
                           const MipPyramid& light_pdf, double light_flux) const {
    const uint32_t flicker_stride = stride_for_width(capture.gbuffer.width, config.flicker_width);
    const std::vector<float> light_texel_flux = view_data(capture, ViewKind::kLight).texel_flux;
    // The flux origin of every frame (FIS, the configured K): where the power comes from, over offsets.
    std::vector<FluxOrigin> origins;
    const auto flicker_of = [&](const std::string& name, float K) {
      FlickerAccumulator acc;
      origins.clear();
      for (uint32_t f = 0; f < config.frames; ++f) {
        const GeneratorRun run = run_generator(device, light, name, config, config.light_vsgls, K, frame_offset_bits(f));
        acc.add_frame(shade_camera_view(device, camera, run.generator->vsgls(), run.generator->vsgl_count(), flicker_stride),
                      power_sum(run.vsgls));
        if (is_fis(name) && K == config.K)
          origins.push_back(flux_origin(run.vsgls, fis_variant(name), light_texel_flux, light_pdf, K));
      }
      return StaticFlicker{acc.weighted_cv(), acc.power_stdev(), acc.power_relative_stdev(), acc.frames()};
    };
    for (const auto& name : config.generators) {
      const auto tg = Clock::now();
      out.flicker_static[name] = flicker_of(name, config.K);
      auto& light_view = out.views.at(view_name(ViewKind::kLight));
      if (!origins.empty() && light_view.generators.at(name).flux_origin)
        light_view.generators.at(name).flux_origin->over_frames = flux_origin_frames(origins);
      say("static flicker " + name + ": " + std::to_string(seconds_since(tg)) + " s");
    }
    out.flicker_image = json::array({shaded_extent(capture.gbuffer.width, flicker_stride),
                                     shaded_extent(capture.gbuffer.height, flicker_stride)});
    out.flicker_gbuffer_stride = flicker_stride;

    std::vector<Rgb8Image> k_tiles;
    for (const auto& name : config.generators) {
      if (!is_fis(name)) continue;
      std::vector<KSweepRow> rows;
      for (float K : config.k_sweep) {
        const auto tg = Clock::now();
        const StaticFlicker flicker = K == config.K ? out.flicker_static.at(name) : flicker_of(name, K);
        const GeneratorRun run = run_generator(device, light, name, config, config.light_vsgls, K, 0);
        const RadianceImage img = K == config.K && reference.k1_images.count(name) > 0
                                      ? reference.k1_images.at(name)
                                      : shade_camera_view(device, camera, run.generator->vsgls(),
                                                          run.generator->vsgl_count(), reference.error_stride);
        KSweepRow row;
        row.K = K;
        row.weighted_cv = flicker.weighted_cv;
        row.power_stdev = flicker.power_stdev;
        row.power_relative_stdev = flicker.power_relative_stdev;
        row.frames = flicker.frames;
        row.error = error_summary(image_error(img, reference.image));
        row.coverage = coverage_with_floor(run.vsgls, light_pdf, floor_light, floor_light_pdf, name, config.light_vsgls, K);
        row.power = power_summary(power_metrics(run.vsgls, light_flux));
        rows.push_back(row);
        k_tiles.push_back(tone_map(downscale(img, kTileFactor), reference.exposure));
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

  // 4b: the animated sequence (moving light and camera), reported separately.
  QualityModel::Animated animated_sequence() const {
    const auto t0 = Clock::now();
    const auto frames = sequence_frames(*config.sequence, config.frames);
    std::map<std::string, FlickerAccumulator> acc;
    FlickerAccumulator ref_acc;
    std::vector<std::string> hashes;
    uint32_t seq_stride = 1, seq_ref_stride = 1;
    std::string seq_scene;
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
      ref_acc.add_frame(ref_img, 0.0);
      for (const auto& name : config.generators) {
        const GeneratorRun run = run_generator(device, lig, name, config, config.light_vsgls, config.K, 0);
        acc[name].add_frame(shade_camera_view(device, cam, run.generator->vsgls(), run.generator->vsgl_count(), seq_stride),
                            power_sum(run.vsgls), ref_img);
      }
    }
    QualityModel::Animated animated;
    for (const auto& name : config.generators)
      animated.generators[name] = {acc[name].weighted_cv(), acc[name].error_cv(), acc[name].power_relative_stdev()};
    animated.sequence = config.sequence->string();
    animated.scene = seq_scene;
    animated.frames = frames.size();
    animated.frame_content_hashes = std::move(hashes);
    animated.gbuffer_stride = seq_stride;
    animated.reference_rsm_stride = seq_ref_stride;
    animated.reference_weighted_cv = ref_acc.weighted_cv();
    animated.note = "light and camera move: weighted_cv includes the true change (compare with the reference's); "
                      "error_cv = sum_p stdev_t(Y - Yref) / sum_p mean_t(Yref) is the change the reference does not have";
    say("animated sequence: " + std::to_string(frames.size()) + " frames in " + std::to_string(seconds_since(t0)) + " s");
    return animated;
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
  out.device_name = device.info().name;
  out.device_driver = device.info().driver_name + " " + device.info().driver_info;
  out.build = build_json();
  out.version = out.build.at("vsgl_bench_version").get<std::string>();
  out.git_commit = out.build.at("git_commit").get<std::string>();
  out.git_dirty = out.build.at("git_dirty").get<bool>();
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
                         {"luminance", "Rec. 709"}};
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

  const DeviceView camera = upload_view(device, capture, ViewKind::kCamera);
  const DeviceView light = upload_view(device, capture, ViewKind::kLight);
  // The lattice floor's input: the same views with the PDF 1 on the texels it weighs (DESIGN.md §11a).
  const Capture floor_capture{capture.meta, uniform_pdf_view(capture.gbuffer), uniform_pdf_view(capture.rsm)};
  const DeviceView floor_camera = upload_view(device, floor_capture, ViewKind::kCamera);
  const DeviceView floor_light = upload_view(device, floor_capture, ViewKind::kLight);
  const MipPyramid floor_light_pdf = view_data(floor_capture, ViewKind::kLight).pdf;
  const QualityRun run{device,       capture,      config,      progress,       capture.meta.scene, camera, light,
                       floor_capture, floor_camera, floor_light, floor_light_pdf};

  MipPyramid light_pdf;
  auto t0 = Clock::now();
  run.view_metrics(out, result, light_pdf);
  out.timings_s.emplace_back("view_metrics", seconds_since(t0));

  t0 = Clock::now();
  const double light_flux = out.views.at("light_view").total_flux;
  const ReferenceShading reference = run.reference_and_errors(out, result, light_flux);
  out.timings_s.emplace_back("reference_and_errors", seconds_since(t0));

  t0 = Clock::now();
  run.flicker_and_k_sweep(out, result, reference, light_pdf, light_flux);
  out.timings_s.emplace_back("flicker_and_k_sweep", seconds_since(t0));

  if (config.sequence) {
    t0 = Clock::now();
    out.flicker_animated = run.animated_sequence();
    out.timings_s.emplace_back("animated_sequence", seconds_since(t0));
  }
  out.timings_s.emplace_back("total", seconds_since(t_start));
  result.json = out;
  return result;
}

}  // namespace vsgl
