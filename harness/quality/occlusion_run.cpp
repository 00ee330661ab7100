#include "harness/quality/occlusion_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "harness/core/error.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/quality/generator_run.hpp"
#include "harness/quality/png_image.hpp"
#include "harness/quality/quality_metrics.hpp"
#include "harness/quality/quality_pictures.hpp"
#include "harness/quality/quality_reference.hpp"
#include "harness/quality/shading_pass.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {

bool OccludedRegion::large_enough() const {
  return occluded_pixels >= kMinOccludedPixels &&
         static_cast<double>(occluded_pixels) >= kMinOccludedShare * static_cast<double>(surface_pixels);
}

namespace {

void require_same_size(const RadianceImage& a, const RadianceImage& b, const char* what) {
  if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size())
    throw InputError(std::string(what) + ": images of different sizes (" + std::to_string(a.width) + "x" +
                     std::to_string(a.height) + " and " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                     ")");
}

bool surface(const glm::vec4& p) { return p.a > 0.0f; }

}  // namespace

OccludedRegion occluded_region(const RadianceImage& unshadowed, const RadianceImage& shadowed) {
  require_same_size(unshadowed, shadowed, "occluded region");
  OccludedRegion o;
  o.inside.assign(unshadowed.pixels.size(), 0);
  double sum0 = 0;
  for (const glm::vec4& p : unshadowed.pixels)
    if (surface(p)) {
      ++o.surface_pixels;
      sum0 += pixel_luminance(p);
    }
  if (o.surface_pixels == 0) return o;
  o.unshadowed_mean_luminance = sum0 / static_cast<double>(o.surface_pixels);
  double removed = 0;
  for (std::size_t i = 0; i < unshadowed.pixels.size(); ++i) {
    if (!surface(unshadowed.pixels[i])) continue;
    const double y0 = pixel_luminance(unshadowed.pixels[i]), yv = pixel_luminance(shadowed.pixels[i]);
    // DESIGN.md §11a.2: visibility removes more than half of the light, on a pixel lit at all.
    if (y0 - yv > kOccludedFraction * y0 && y0 > kLitFraction * o.unshadowed_mean_luminance) {
      o.inside[i] = 1;
      ++o.occluded_pixels;
      removed += y0 - yv;
    }
  }
  o.occluded_light_share = sum0 > 0 ? removed / sum0 : 0.0;
  return o;
}

double region_relative_rmse(const RadianceImage& frame, const RadianceImage& reference,
                            const std::vector<uint8_t>& region) {
  require_same_size(frame, reference, "relative RMSE over the occluded region");
  if (region.size() != reference.pixels.size())
    throw InputError("relative RMSE over the occluded region: the region has " + std::to_string(region.size()) +
                     " pixels, the images " + std::to_string(reference.pixels.size()));
  double num = 0, den = 0;
  for (std::size_t i = 0; i < region.size(); ++i) {
    if (!region[i]) continue;
    const glm::dvec3 l(frame.pixels[i]), r(reference.pixels[i]);
    const glm::dvec3 d = l - r;
    num += glm::dot(d, d);
    den += glm::dot(r, r);
  }
  return den > 0 ? std::sqrt(num / den) : std::numeric_limits<double>::infinity();
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The VPLs of the RSM at `stride` (every lit texel, as the quality reference's) shaded with `shading`.
struct ShadedVpls {
  uint64_t vpls = 0;
  RadianceImage image;
};
ShadedVpls shade_vpls(const OcclusionInputs& in, VisibleShading& shading, uint32_t stride) {
  const std::vector<VsglRecord> vpls =
      reference_vpls(in.reference_rsm, in.capture.meta.light, stride, VplExtent::kTexelFootprint, VplSet::kAllLit);
  FixedVsglGenerator set(in.device, vpls, "occlusion_reference");
  return {vpls.size(), shading.shade(in.camera, set.vsgls(), set.vsgl_count(), in.error_stride)};
}

// O outlined in cyan on a tile: the pixels of O with a neighbour outside it.
void outline(Rgb8Image& tile, const std::vector<uint8_t>& region) {
  const auto in_region = [&](int64_t x, int64_t y) {
    if (x < 0 || y < 0 || x >= tile.width || y >= tile.height) return false;
    return region[static_cast<std::size_t>(y) * tile.width + static_cast<std::size_t>(x)] != 0;
  };
  for (int64_t y = 0; y < tile.height; ++y)
    for (int64_t x = 0; x < tile.width; ++x) {
      if (!in_region(x, y)) continue;
      if (in_region(x - 1, y) && in_region(x + 1, y) && in_region(x, y - 1) && in_region(x, y + 1)) continue;
      uint8_t* p = &tile.rgb[(static_cast<std::size_t>(y) * tile.width + static_cast<std::size_t>(x)) * 3];
      p[0] = 0;
      p[1] = 255;
      p[2] = 255;
    }
}

}  // namespace

OcclusionResult measure_occlusion(const OcclusionInputs& in) {
  const QualityConfig& config = in.config;
  if (config.visibility.mode == ShadingVisibility::kNone)
    throw InputError("Fig. 7 (the occluded light) needs a visibility: --visibility ism or exact");
  const ShadingVisibilitySettings exact_settings{ShadingVisibility::kExact, {}};
  VisibleShading exact(in.device, exact_settings, &in.geometry);
  VisibleShading unshadowed(in.device, ShadingVisibilitySettings{}, nullptr);
  VisibleShading frames_shading(in.device, config.visibility, &in.geometry);
  frames_shading.require_maps_fit(config.light_vsgls);

  OcclusionResult result;
  OcclusionMeasure& m = result.measure;
  m.visibility = shading_visibility_text(config.visibility);
  const ViewImage& rsm = in.reference_rsm;
  const uint32_t side = std::max(rsm.width, rsm.height);
  const uint32_t stride = reference_stride(
      rsm, config.visibility_reference_rsm != 0 ? config.visibility_reference_rsm : config.reference_rsm);
  m.reference_rsm_stride = stride;
  m.reference_rsm_side = (side + stride - 1) / stride;

  // R_v's ladder (DESIGN.md §11a.2): its rungs at 8, 4 and 2 times its stride, coarsest first, each
  // leaving at least 2 texels a side, then R_v itself.
  const auto t0 = Clock::now();
  std::vector<uint32_t> strides;
  for (uint32_t k : kConvergenceStrides)
    if (stride * k * 2 <= side) strides.push_back(stride * k);
  strides.push_back(stride);
  std::vector<RadianceImage> rungs;
  for (uint32_t s : strides) {
    const auto ts = Clock::now();
    ShadedVpls shaded = shade_vpls(in, exact, s);
    if (s == stride) m.reference_vpls = shaded.vpls;
    rungs.push_back(std::move(shaded.image));
    in.say("occlusion: exact reference at RSM stride " + std::to_string(s) + " (" + std::to_string(shaded.vpls) +
           " VPLs) in " + std::to_string(seconds_since(ts)) + " s");
  }
  m.reference_seconds = seconds_since(t0);
  const RadianceImage reference = rungs.back();
  const RadianceImage reference_unshadowed = shade_vpls(in, unshadowed, stride).image;

  const OccludedRegion region = occluded_region(reference_unshadowed, reference);
  m.surface_pixels = region.surface_pixels;
  m.occluded_pixels = region.occluded_pixels;
  m.unshadowed_mean_luminance = region.unshadowed_mean_luminance;
  m.occluded_light_share = region.occluded_light_share;
  m.region_rule =
      "pixels with a surface where Y_0 - Y_v > 0.5 Y_0 and Y_0 > 0.05 mean Y_0 (R_0 and R_v the VPL reference "
      "without and with exact visibility); at least 50 pixels and 1 % of the surface pixels";
  in.say("occlusion: " + std::to_string(region.occluded_pixels) + " of " + std::to_string(region.surface_pixels) +
         " surface pixels occluded");

  // A rung black over O (a coarse one whose few VPLs are all occluded there) has no relative error
  // there: it and the rungs coarser than it leave the ladder.
  const auto lit_over_region = [&](const RadianceImage& rung) {
    return std::isfinite(region_relative_rmse(rung, rung, region.inside));
  };
  std::size_t first = rungs.size();
  while (first > 0 && lit_over_region(rungs[first - 1])) --first;
  if (first > 0) {
    in.say("occlusion: " + std::to_string(first) + " coarse rung(s) black over the occluded region left out");
    rungs.erase(rungs.begin(), rungs.begin() + static_cast<std::ptrdiff_t>(std::min(first, rungs.size())));
    strides.erase(strides.begin(), strides.begin() + static_cast<std::ptrdiff_t>(std::min(first, strides.size())));
  }
  m.ladder.rsm_strides = strides;
  for (uint32_t s : strides) m.ladder.rsm_sides.push_back((side + s - 1) / s);
  for (const RadianceImage& rung : rungs) m.ladder.mean_luminances.push_back(mean_surface_luminance(rung));
  std::vector<double> differences;
  for (std::size_t i = 0; i + 1 < rungs.size(); ++i)
    differences.push_back(region_relative_rmse(rungs[i], rungs[i + 1], region.inside));
  m.ladder.metrics["relative_rmse"] = reference_ladder_metric(differences);
  m.ladder.note = std::to_string(rungs.size()) + " rungs of R_v, relative RMSE over the occluded region";

  FrameErrors& frames = m.frames;
  frames.gbuffer_stride = in.error_stride;
  frames.image = nlohmann::ordered_json::array({reference.width, reference.height});
  frames.reference = "R_v, the VPL reference with exact visibility; relative RMSE over the occluded region";
  if (rungs.size() >= 2) frames.second_rung_reference = "R_v's stride-2 rung, the same pixels and region";
  if (rungs.size() >= 3) frames.coarse_rung_strides.assign(strides.begin(), strides.end() - 2);
  m.control_frames = std::min(config.control_frames, config.frames);

  const float exposure = auto_exposure(reference);
  std::vector<Rgb8Image> top{tone_map(reference, exposure), tone_map(reference_unshadowed, exposure)};
  std::vector<Rgb8Image> bottom{error_map(reference, reference, 1.0f),
                                error_map(reference_unshadowed, reference, 1.0f)};
  if (!region.large_enough() || rungs.empty()) {
    m.note = rungs.empty() ? "no light in the occluded region: R_v is black over O"
                           : "no occluded region: " + std::to_string(region.occluded_pixels) + " pixel(s) of " +
                                 std::to_string(region.surface_pixels) + " in O, fewer than " +
                                 std::to_string(kMinOccludedPixels) + " or 1 %";
  } else {
    for (const std::string& name : config.generators) {
      const auto tg = Clock::now();
      std::vector<double>& errors = frames.generators[name]["relative_rmse"];
      std::vector<std::vector<double>> coarse(frames.coarse_rung_strides.size());
      for (uint32_t f = 0; f < config.frames; ++f) {
        const GeneratorRun run =
            run_generator(in.device, in.light, name, config, config.light_vsgls, config.K, frame_offset_bits(f));
        const RadianceImage img =
            frames_shading.shade(in.camera, run.generator->vsgls(), run.generator->vsgl_count(), in.error_stride);
        errors.push_back(region_relative_rmse(img, reference, region.inside));
        if (rungs.size() >= 2)
          frames.second_rung[name]["relative_rmse"].push_back(
              region_relative_rmse(img, rungs[rungs.size() - 2], region.inside));
        for (std::size_t r = 0; r < coarse.size(); ++r)
          coarse[r].push_back(region_relative_rmse(img, rungs[r], region.inside));
        if (f < m.control_frames) {
          const RadianceImage control =
              exact.shade(in.camera, run.generator->vsgls(), run.generator->vsgl_count(), in.error_stride);
          m.control[name].push_back(region_relative_rmse(control, reference, region.inside));
        }
        if (f == 0) {
          top.push_back(tone_map(img, exposure));
          bottom.push_back(error_map(img, reference, 1.0f));
        }
      }
      for (std::vector<double>& c : coarse) frames.coarse_rungs[name].push_back({{"relative_rmse", std::move(c)}});
      in.say("occlusion frames " + name + ": " + std::to_string(seconds_since(tg)) + " s");
    }
  }
  for (Rgb8Image& tile : top) outline(tile, region.inside);
  for (Rgb8Image& tile : bottom) outline(tile, region.inside);
  const auto columns = static_cast<uint32_t>(top.size());
  top.insert(top.end(), bottom.begin(), bottom.end());
  std::string order = "R_v (exact visibility), R_0 (none)";
  if (region.large_enough())
    for (const std::string& name : config.generators) order += ", " + name;
  result.pictures.push_back(
      {in.capture.meta.scene + "_occlusion.png",
       "Fig. 7 analog. Top row: " + order + " at lattice offset 0 (" + m.visibility +
           "), one exposure; the occluded region O outlined in cyan. Bottom row: |dY| / mean Y of R_v (black 0, "
           "red, yellow, white >= 1)",
       tile_grid(top, columns)});
  return result;
}

}  // namespace vsgl
