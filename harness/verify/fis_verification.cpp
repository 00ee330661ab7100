#include "harness/verify/fis_verification.hpp"

#include <algorithm>
#include <cmath>

#include "harness/core/error.hpp"
#include "harness/core/generator_ids.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/vk/device_info.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/reference/fis_reference.hpp"

namespace vsgl {
namespace {

// A GPU sampler may choose another child than the CPU only where the CPU's decision was a near tie
// (a GPU's division need not be correctly rounded); such samples are excused and counted.
constexpr float kTieMargin = 1e-5f;

std::string num(double v, int digits = 3) { return check_number(v, digits); }

struct GpuRun {
  MomentPyramids pyramid;  // as computed on the device
  std::vector<VsglRecord> vsgls;
};

GpuRun run_on_device(Device& device, const DeviceView& view, FisVariant variant, const FisParams& params) {
  FisGenerator gen(device, view, variant, params);
  run_untimed(device, gen);
  const VirtualSquare& sq = view.square;
  const auto all = gen.download_pyramid(device);
  GpuRun run;
  for (uint32_t layer = 0; layer < kMomentLayerCount; ++layer) {
    run.pyramid[layer].square = sq;
    run.pyramid[layer].texels.assign(all.begin() + layer * std::ptrdiff_t{sq.total_texels()},
                                     all.begin() + (layer + 1) * std::ptrdiff_t{sq.total_texels()});
  }
  run.vsgls = download_vector<VsglRecord>(device, gen.vsgls(), params.vsgl_count);
  return run;
}

// max |a - b| / max |b| over one layer's texels and components (DESIGN.md §11's normalized error).
double normalized_error(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b, std::size_t count) {
  double diff = 0, scale = 0;
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < 4; ++c) {
      diff = std::max(diff, std::abs(double{a[i][c]} - double{b[i][c]}));
      scale = std::max(scale, std::abs(double{b[i][c]}));
    }
  return scale > 0 ? diff / scale : diff;
}

class ViewVerifier {
 public:
  ViewVerifier(Device& device, const Capture& capture, ViewKind kind, const VerifyConfig& config)
      : device_(device), capture_(capture), view_(upload_view(device, capture, kind)), config_(config) {
    params_.vsgl_count = std::min(kind == ViewKind::kCamera ? config.camera_vsgls : config.light_vsgls,
                                  view_.samplable_texels);
    params_.K = config.K;
    params_.bisection_iterations = config.bisection_iterations;
    params_.mipmapping = config.mipmapping.value_or(default_mip_strategy(device.info()));
    precision_ = FilterPrecision{device.info().sub_texel_precision_bits, device.info().mipmap_precision_bits};
  }

  void run(std::vector<CheckResult>& out) {
    const auto cpu_moments = reference_moments(capture_.view(view_.kind), view_.source_position);
    for (PyramidPath requested : config_.pyramids) {
      std::string fallback;
      params_.pyramid = effective_pyramid_path(device_.info(), requested, &fallback);
      if (!fallback.empty()) {
        CheckResult r = result("fis", "texture_path");
        r.measured = 1;
        r.tolerance = 0;
        r.detail = "texture path unavailable: " + fallback + " (the buffer path is checked instead)";
        out.push_back(r);
      }
      if (params_.pyramid == PyramidPath::kBuffer) {
        // The buffer pyramid binds all moment layers as one storage buffer; a view too large for
        // the device's maxStorageBufferRange cannot take that path at all (DESIGN.md §11): say so
        // and check the texture path only, rather than failing the device.
        try {
          run_path(out, cpu_moments);
        } catch (const DeviceLimitError& e) {
          CheckResult r = result("fis[buffer]", "buffer_path");
          r.measurement = true;
          r.detail = std::string("not run on this device: ") + e.what();
          out.push_back(r);
        }
        continue;
      }
      run_path(out, cpu_moments);
    }
  }

 private:
  // The path under test, in every check's generator column: the generator id and the path, as in
  // fis_modified[texture/single-pass].
  std::string path_label() const {
    return params_.pyramid == PyramidPath::kBuffer
               ? std::string("buffer")
               : std::string("texture/") + mip_strategy_name(*params_.mipmapping);
  }
  std::string labelled(const std::string& gen) const { return gen + "[" + path_label() + "]"; }
  bool texture() const { return params_.pyramid == PyramidPath::kTexture; }

  void run_path(std::vector<CheckResult>& out, const MomentLayers& cpu_moments) {
    if (texture()) check_other_strategies(out);
    for (FisVariant variant : {FisVariant::kTok15, FisVariant::kModified}) {
      const GpuRun gpu = run_on_device(device_, view_, variant, params_);
      MomentPyramids chain;  // the CPU mip chain of the device's level 0
      for (uint32_t layer = 0; layer < kMomentLayerCount; ++layer) {
        const auto& t = gpu.pyramid[layer].texels;
        chain[layer] = MipPyramid::build({t.begin(), t.begin() + view_.square.level_texels(0)}, view_.square.width,
                                         view_.square.height);
      }
      const std::string gen = labelled(fis_variant_name(variant));
      check_moments(out, gen, gpu, cpu_moments);
      check_pyramid(out, gen, gpu, chain);
      // The later passes are checked on the pyramid they read: the CPU chain (bit-exact with the
      // device's for every kernel of ours), or the blit's own, whose bound check_pyramid states.
      const bool blit = texture() && *params_.mipmapping == MipStrategy::kBlit;
      const MomentPyramids& read = blit ? gpu.pyramid : chain;
      const auto samples = reference_samples(read[2], params_.vsgl_count, params_.offset_bits);
      check_sampler(out, gen, gpu, samples);
      check_levels(out, variant, gpu, read, samples);
      check_generator(out, variant, gpu, read, samples);
      check_total_power(out, variant, gpu, read, samples);
    }
    check_histogram(out);
  }

  // The texture path's other mipmapping strategies build the same pyramid (DESIGN.md §6.1a: all
  // verified): each against the CPU chain of its own level 0.
  void check_other_strategies(std::vector<CheckResult>& out) const {
    for (MipStrategy m : {MipStrategy::kSinglePass, MipStrategy::kBlit, MipStrategy::kPerLevel}) {
      if (m == *params_.mipmapping) continue;
      FisParams p = params_;
      p.mipmapping = m;
      const GpuRun gpu = run_on_device(device_, view_, FisVariant::kModified, p);
      MomentPyramids chain;
      for (uint32_t layer = 0; layer < kMomentLayerCount; ++layer) {
        const auto& t = gpu.pyramid[layer].texels;
        chain[layer] = MipPyramid::build({t.begin(), t.begin() + view_.square.level_texels(0)}, view_.square.width,
                                         view_.square.height);
      }
      check_pyramid(out, std::string(kFisModified) + "[texture/" + mip_strategy_name(m) + "]", gpu, chain);
    }
  }

  CheckResult result(const std::string& generator, const std::string& check) const {
    CheckResult r;
    r.view = view_.label;
    r.generator = generator;
    r.check = check;
    return r;
  }

  // "additional": level 0 against the CPU moments; transcendental functions differ in the last bits.
  void check_moments(std::vector<CheckResult>& out, const std::string& gen, const GpuRun& gpu,
                     const MomentLayers& cpu) const {
    CheckResult r = result(gen, "moments");
    for (uint32_t layer = 0; layer < kMomentLayerCount; ++layer)
      r.measured = std::max(r.measured, normalized_error(gpu.pyramid[layer].texels, cpu[layer],
                                                         view_.square.level_texels(0)));
    r.tolerance = 1e-5;
    r.detail = "normalized max error of the " + std::to_string(kMomentLayerCount) +
               " moment layers vs the CPU additional pass";
    out.push_back(r);
  }

  // "mipmapping": every level against the CPU chain of the same level 0 (float sums: 1e-6).
  void check_pyramid(std::vector<CheckResult>& out, const std::string& gen, const GpuRun& gpu,
                     const MomentPyramids& chain) const {
    CheckResult r = result(gen, "pyramid");
    if (gen.find("/blit") != std::string::npos) {
      // The driver's blit samples between the children only to subTexelPrecisionBits.
      for (uint32_t layer = 0; layer < kMomentLayerCount; ++layer)
        r.measured = std::max(r.measured, blit_chain_error_ratio(gpu.pyramid[layer], precision_));
      r.tolerance = 1.0;
      r.detail = "max |texel - mean of its 4 children| / bound over all " + num(view_.square.levels + 1) +
                 " levels of " + std::to_string(kMomentLayerCount) + " layers; bound: 2^-" +
                 num(precision_.sub_texel_bits) +
                 " (subTexelPrecisionBits) of the children's differences + 2^-20 of their magnitude";
      out.push_back(r);
      return;
    }
    for (uint32_t layer = 0; layer < kMomentLayerCount; ++layer)
      r.measured = std::max(r.measured, normalized_error(gpu.pyramid[layer].texels, chain[layer].texels,
                                                         chain[layer].texels.size()));
    r.tolerance = 1e-6;
    r.detail = "normalized max error over all " + num(view_.square.levels + 1) + " levels of " +
               std::to_string(kMomentLayerCount) + " layers";
    out.push_back(r);
  }

  bool excused(const SamplePoint& s, const VsglRecord& v) const {
    const glm::uvec2 texel(glm::vec2(v.center_pdf) * static_cast<float>(view_.square.size));
    return texel != s.texel && s.min_margin < kTieMargin;
  }

  void check_sampler(std::vector<CheckResult>& out, const std::string& gen, const GpuRun& gpu,
                     const std::vector<SamplePoint>& samples) const {
    CheckResult r = result(gen, "sampler");
    uint32_t wrong = 0, ties = 0;
    double max_dx = 0;
    for (uint32_t i = 0; i < samples.size(); ++i) {
      const VsglRecord& v = gpu.vsgls[i];
      const glm::uvec2 texel(glm::vec2(v.center_pdf) * static_cast<float>(view_.square.size));
      if (texel != samples[i].texel) {
        (samples[i].min_margin < kTieMargin ? ties : wrong) += 1;
        continue;
      }
      max_dx = std::max(max_dx, double{glm::length(glm::vec2(v.center_pdf) - samples[i].x)});
    }
    r.measured = wrong + (max_dx > 1e-6 ? 1 : 0);
    r.tolerance = 0;
    r.detail = "kernel centres in another texel than the CPU's (near ties excused: " + num(ties) +
               "); max |dx| " + num(max_dx, 2);
    out.push_back(r);
  }

  // Eq. 1 levels (Tok15) or the Eq. 3 residual (modified), recomputed on the CPU from the device's
  // own kernel centres and pyramid.
  void check_levels(std::vector<CheckResult>& out, FisVariant variant, const GpuRun& gpu, const MomentPyramids& chain,
                    const std::vector<SamplePoint>& samples) const {
    const VirtualSquare& sq = view_.square;
    const float L = static_cast<float>(sq.levels);
    if (variant == FisVariant::kTok15) {
      CheckResult r = result(labelled(fis_variant_name(variant)), "eq1_levels");
      for (uint32_t i = 0; i < samples.size(); ++i) {
        const float expected = tok15_level(gpu.vsgls[i].center_pdf.z, params_.vsgl_count, params_.K, sq);
        r.measured = std::max(r.measured, double{std::abs(gpu.vsgls[i].axis_level.w - expected)});
      }
      r.tolerance = 1e-4;
      r.detail = "max |l_i - clamp(0.5 log2(K M / (N p(x_i))), 0, L)| over every VSGL";
      out.push_back(r);
      return;
    }
    CheckResult r = result(labelled(fis_variant_name(variant)), "eq3_residual");
    const float tol = bisection_tolerance(sq.levels, params_.bisection_iterations);
    const float target = params_.K / static_cast<float>(params_.vsgl_count);
    const float q_top = chain[2].top().w;
    const auto M = static_cast<float>(sq.square_texels());
    // The texture path's g(l) is the device's filter: off from the CPU's by at most the bound of
    // fetch_error_bound() (subTexelPrecisionBits, mipmapPrecisionBits), scaled like g.
    auto slack = [&](glm::vec2 x, float l) {
      if (!texture()) return 0.0f;
      return std::exp2(2.0f * l) / M * fetch_error_bound(chain[2], x, l, precision_).w / q_top;
    };
    uint32_t interior = 0, violations = 0;
    double worst = 0, worst_slack = 0;
    for (uint32_t i = 0; i < samples.size(); ++i) {
      const float l = gpu.vsgls[i].axis_level.w;
      if (l <= 0.0f || l >= L) continue;  // at a bound Eq. 3 has no root inside [0, L]
      ++interior;
      const glm::vec2 x(gpu.vsgls[i].center_pdf);
      // A slack of 1e-5 relative covers float rounding of the device's own evaluation of g.
      const float l_lo = std::max(0.0f, l - tol), l_hi = std::min(L, l + tol);
      const float lo = modified_kernel_mass(chain[2], x, l_lo) - slack(x, l_lo);
      const float hi = modified_kernel_mass(chain[2], x, l_hi) + slack(x, l_hi);
      if (!(lo <= target * (1.0f + 1e-5f) && target <= hi * (1.0f + 1e-5f))) ++violations;
      worst = std::max(worst, std::abs(double{modified_kernel_mass(chain[2], x, l)} / double{target} - 1.0));
      worst_slack = std::max(worst_slack, double{slack(x, l)} / double{target});
    }
    r.measured = violations;
    r.tolerance = 0;
    r.detail = "VSGLs (of " + num(interior, 9) + " not at a bound) whose root of a(l) p(x_i,l) = K/N lies outside l_i +- " +
               num(tol, 2) + "; max |a p / (K/N) - 1| = " + num(worst) +
               (texture() ? "; filter bound (subTexel " + num(precision_.sub_texel_bits) + ", mipmap " +
                                num(precision_.mipmap_bits) + " bits) up to " + num(worst_slack) + " of K/N"
                          : std::string());
    out.push_back(r);
  }

  // The whole filtered-sampling pass against reference_fis on the same pyramid.
  void check_generator(std::vector<CheckResult>& out, FisVariant variant, const GpuRun& gpu,
                       const MomentPyramids& chain, const std::vector<SamplePoint>& samples) const {
    if (texture()) {
      check_generator_texture(out, variant, gpu, chain, samples);
      return;
    }
    CheckResult r = result(labelled(fis_variant_name(variant)), "vsgls");
    const auto expected = reference_fis(chain, variant, params_);
    double worst_power = 0, worst_level = 0;
    for (uint32_t i = 0; i < expected.size(); ++i) {
      if (excused(samples[i], gpu.vsgls[i])) continue;
      const glm::vec3 a = gpu.vsgls[i].power(), b = expected[i].power();
      const double scale = double{std::max({b.r, b.g, b.b})} + 1e-30;
      worst_power = std::max(worst_power, double{glm::length(a - b)} / scale);
      worst_level = std::max(worst_level, double{std::abs(gpu.vsgls[i].axis_level.w - expected[i].axis_level.w)});
    }
    // A bisection step may flip on a last-bit difference: the level then moves by one step and the
    // power by the footprint's change over it.
    r.measured = worst_power;
    r.tolerance = 5e-3;
    r.detail = "max relative power error vs the CPU generator (max level difference " + num(worst_level, 2) + ")";
    out.push_back(r);
  }

  // The texture path against the CPU generator at the device's own levels (Eq. 3's root is checked
  // by eq3_residual): every power within the bound the filter precision allows (per VSGL and
  // channel, propagated through Eq. 4/5) plus 1e-4 relative for float rounding. Measured: the
  // worst error / tolerance (passes at <= 1).
  void check_generator_texture(std::vector<CheckResult>& out, FisVariant variant, const GpuRun& gpu,
                               const MomentPyramids& chain, const std::vector<SamplePoint>& samples) const {
    CheckResult r = result(labelled(fis_variant_name(variant)), "vsgls");
    const auto cpu_generator = reference_fis(chain, variant, params_);
    double worst_ratio = 0, worst_rel = 0, worst_level = 0;
    uint32_t excused_count = 0;
    for (uint32_t i = 0; i < samples.size(); ++i) {
      if (excused(samples[i], gpu.vsgls[i])) {
        ++excused_count;
        continue;
      }
      const float l = gpu.vsgls[i].axis_level.w;
      const auto [expected, bound] = fis_power_bound(variant, chain, samples[i], l, params_, precision_);
      const glm::vec3 got = gpu.vsgls[i].power();
      const double scale = double{std::max({std::abs(expected.r), std::abs(expected.g), std::abs(expected.b)})} + 1e-30;
      for (int c = 0; c < 3; ++c) {
        const double err = std::abs(double{got[c]} - double{expected[c]});
        worst_ratio = std::max(worst_ratio, err / (double{bound[c]} + 1e-4 * scale));
        worst_rel = std::max(worst_rel, err / scale);
      }
      worst_level = std::max(worst_level, double{std::abs(l - cpu_generator[i].axis_level.w)});
    }
    r.measured = worst_ratio;
    r.tolerance = 1.0;
    r.detail = "max power error / (filter bound + 1e-4 rel.) vs the CPU generator at the device's levels; max "
               "relative power error " + num(worst_rel) + "; max level difference to the CPU's own levels " +
               num(worst_level, 2) + " (near ties excused: " + num(excused_count) + ")";
    out.push_back(r);
  }

  // Sum of the VSGLs' power. Pass/fail (buffer path): the device's sum against the CPU generator's
  // on the same pyramid (correctness; the texture path's per-VSGL filter bound in `vsgls` already
  // covers it). Reported: the sum over the view's total reflectance / flux, which FIS only
  // estimates (exact in expectation only where the PDF is proportional to the power; on a
  // high-frequency BRSM PDF Tok15 drifts from 1, the paper's point), so no tolerance is set on it.
  void check_total_power(std::vector<CheckResult>& out, FisVariant variant, const GpuRun& gpu,
                         const MomentPyramids& chain, const std::vector<SamplePoint>& samples) const {
    const std::string gen = labelled(fis_variant_name(variant));
    double sum = 0;
    for (const auto& v : gpu.vsgls) sum += double{v.power().r} + double{v.power().g} + double{v.power().b};
    if (!texture()) {
      const auto expected = reference_fis(chain, variant, params_);
      double reference = 0;
      uint32_t excused_count = 0;
      for (uint32_t i = 0; i < expected.size(); ++i) {
        const double g = double{gpu.vsgls[i].power().r} + double{gpu.vsgls[i].power().g} + double{gpu.vsgls[i].power().b};
        // An excused sample (a near tie the device decided the other way) counts as the device's.
        reference += excused(samples[i], gpu.vsgls[i]) ? (++excused_count, g)
                                                       : double{expected[i].power().r} + double{expected[i].power().g} +
                                                             double{expected[i].power().b};
      }
      CheckResult check = result(gen, "power_vs_cpu");
      check.measured = reference > 0 ? std::abs(sum / reference - 1.0) : std::abs(sum);
      // Each VSGL's power is within the vsgls check's 5e-3 of the CPU's, so their sum is too.
      check.tolerance = 5e-3;
      check.detail = "|sum of VSGL power (device) / sum (CPU generator) - 1|" +
                     (excused_count > 0 ? "; " + num(excused_count) + " near-tie samples taken as the device's" : "");
      out.push_back(check);
    }
    const glm::vec4 top = chain[0].top();  // mean over the square
    const double total = (double{top.r} + double{top.g} + double{top.b}) * view_.square.square_texels();
    CheckResult r = result(gen, "total_power");
    r.measurement = true;
    r.measured = sum / total;
    r.expected = 1.0;
    r.detail = std::string("sum of VSGL power / total ") + (view_.kind == ViewKind::kCamera ? "reflectance" : "flux") +
               ": an estimate (exact only where the PDF is proportional to the power)";
    out.push_back(r);
  }

  // Many kernel centres drawn on the device follow the PDF: total variation distance between their
  // histogram on an 8x8 grid of the square and the PDF's mass in each cell.
  void check_histogram(std::vector<CheckResult>& out) const {
    FisParams p = params_;
    p.vsgl_count = std::min(config_.histogram_samples, view_.samplable_texels);
    const GpuRun gpu = run_on_device(device_, view_, FisVariant::kModified, p);
    const VirtualSquare& sq = view_.square;
    const uint32_t grid_level = sq.levels >= 3 ? sq.levels - 3 : 0;
    const uint32_t cells = sq.size >> grid_level;  // 8 (fewer for tiny squares)
    std::vector<double> observed(std::size_t{cells} * cells, 0.0);
    for (const auto& v : gpu.vsgls) {
      const glm::uvec2 c = glm::min(glm::uvec2(glm::vec2(v.center_pdf) * static_cast<float>(cells)), cells - 1);
      observed[std::size_t{c.y} * cells + c.x] += 1.0 / p.vsgl_count;
    }
    const auto& q = gpu.pyramid[2];
    const double qL = double{q.top().w};
    double tv = 0;
    for (uint32_t y = 0; y < cells; ++y)
      for (uint32_t x = 0; x < cells; ++x) {
        const double expected = double{q.at(grid_level, static_cast<int32_t>(x), static_cast<int32_t>(y)).w} / qL /
                                (static_cast<double>(cells) * cells);
        tv += 0.5 * std::abs(observed[std::size_t{y} * cells + x] - expected);
      }
    CheckResult r = result(labelled("sampler"), "histogram");
    r.measured = tv;
    r.tolerance = 4.0 / std::sqrt(static_cast<double>(p.vsgl_count)) * 0.25;
    r.detail = "total variation distance, " + num(p.vsgl_count, 9) + " kernel centres on a " + num(cells) + "x" +
               num(cells) + " grid vs the PDF";
    out.push_back(r);
  }

  Device& device_;
  const Capture& capture_;
  DeviceView view_;
  VerifyConfig config_;
  FisParams params_;
  FilterPrecision precision_;
};

}  // namespace

std::vector<CheckResult> verify_fis(Device& device, const Capture& capture, const VerifyConfig& config) {
  std::vector<CheckResult> out;
  for (ViewKind kind : {ViewKind::kCamera, ViewKind::kLight}) {
    ViewVerifier verifier(device, capture, kind, config);
    verifier.run(out);
  }
  return out;
}

}  // namespace vsgl
