// CPU reference of the FIS generators; the operation order of every float expression follows
// the FIS conventions shared with the GLSL kernels (kernels/CONVENTIONS.md), which is what lets the pyramid and the
// sampler's texel choices match the GPU exactly.
#include "harness/reference/fis_reference.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "harness/core/error.hpp"

namespace vsgl {

namespace {

// Largest float below 1: where a rescaled u is clamped so that u < 1 keeps holding.
constexpr float kOneMinusUlp = 0x1.fffffep-1f;
// The Fibonacci lattice's golden-ratio step, 2^32 / phi rounded (DESIGN.md §5).
constexpr uint32_t kGoldenStep = 2654435769u;

float pdf_weight(const MipPyramid& q, uint32_t level, int32_t x, int32_t y) { return q.at(level, x, y).w; }

// The mean of q over the square; InputError when there is nothing to sample.
float pdf_total(const MipPyramid& q) {
  const float qL = q.top().w;
  if (!(qL > 0.0f) || !std::isfinite(qL))
    throw InputError("PDF is zero everywhere (or not finite): no kernel centre can be sampled");
  return qL;
}

// GLSL's mix(a, b, t) as the specification defines it: a * (1 - t) + b * t.
glm::vec4 mix_levels(glm::vec4 a, glm::vec4 b, float t) { return a * (1.0f - t) + b * t; }

}  // namespace

// ---- pyramid -------------------------------------------------------------------------------

MipPyramid MipPyramid::build(const std::vector<glm::vec4>& level0, uint32_t w, uint32_t h) {
  MipPyramid p;
  p.square = VirtualSquare::make(w, h, "mip pyramid");
  if (level0.size() != std::size_t{w} * h)
    throw InputError("mip pyramid: level 0 has " + std::to_string(level0.size()) + " texels, expected " +
                     std::to_string(w) + "x" + std::to_string(h));
  p.texels.resize(p.square.total_texels());
  std::copy(level0.begin(), level0.end(), p.texels.begin());
  for (uint32_t l = 0; l < p.square.levels; ++l) {
    const uint32_t offset = p.square.level_offset(l + 1);
    const uint32_t wl = p.square.level_width(l + 1);
    const uint32_t hl = p.square.level_height(l + 1);
    for (uint32_t j = 0; j < hl; ++j) {
      for (uint32_t i = 0; i < wl; ++i) {
        const auto ci = static_cast<int32_t>(2 * i);
        const auto cj = static_cast<int32_t>(2 * j);
        const glm::vec4 c00 = p.at(l, ci, cj);
        const glm::vec4 c10 = p.at(l, ci + 1, cj);
        const glm::vec4 c01 = p.at(l, ci, cj + 1);
        const glm::vec4 c11 = p.at(l, ci + 1, cj + 1);
        p.texels[offset + j * wl + i] = (c00 + c10 + c01 + c11) * 0.25f;
      }
    }
  }
  return p;
}

glm::vec4 MipPyramid::at(uint32_t level, int32_t x, int32_t y) const {
  if (level > square.levels || x < 0 || y < 0) return glm::vec4(0.0f);
  const uint32_t wl = square.level_width(level);
  const uint32_t hl = square.level_height(level);
  const auto ux = static_cast<uint32_t>(x);
  const auto uy = static_cast<uint32_t>(y);
  if (ux >= wl || uy >= hl) return glm::vec4(0.0f);
  return texels[square.level_offset(level) + uy * wl + ux];
}

MomentPyramids build_moment_pyramids(const MomentLayers& level0, uint32_t w, uint32_t h) {
  MomentPyramids out;
  for (std::size_t layer = 0; layer < kMomentLayerCount; ++layer) out[layer] = MipPyramid::build(level0[layer], w, h);
  return out;
}

// ---- moments -------------------------------------------------------------------------------

MomentLayers reference_moments(const ViewImage& view, glm::vec3 source_pos) {
  const std::size_t n = view.texels();
  for (int c = 0; c < kChannelCount; ++c) {
    const bool pdf_absent = c == kPdf && !view.has_pdf && view.planes[c].empty();
    if (view.planes[c].size() != n && !pdf_absent)
      throw InputError(std::string(view_label(view.kind)) + ": channel " + channel_names(view.kind)[c] + " has " +
                       std::to_string(view.planes[c].size()) + " texels, expected " + std::to_string(n));
  }
  const bool camera_view = view.kind == ViewKind::kCamera;
  MomentLayers layers;
  for (auto& layer : layers) layer.resize(n);
  const auto& pl = view.planes;
  for (std::size_t t = 0; t < n; ++t) {
    const float pdf = pl[kPdf].empty() ? 0.0f : pl[kPdf][t];
    const TexelMoments m = texel_moments(
        pl[kValid][t] != 0.0f, {pl[kPX][t], pl[kPY][t], pl[kPZ][t]}, {pl[kNX][t], pl[kNY][t], pl[kNZ][t]},
        {pl[kDR][t], pl[kDG][t], pl[kDB][t]}, {pl[kSR][t], pl[kSG][t], pl[kSB][t]}, pl[kRoughness][t], pdf,
        source_pos, camera_view);
    layers[0][t] = m.m0;
    layers[1][t] = m.m1;
    layers[2][t] = m.m2;
    layers[3][t] = m.m3;
    layers[4][t] = m.m4;
  }
  return layers;
}

// ---- sampler -------------------------------------------------------------------------------

glm::vec2 fibonacci_point(uint32_t i, uint32_t N, uint32_t offset_bits) {
  const uint32_t y_bits = i * kGoldenStep + offset_bits;  // mod 2^32
  return {(static_cast<float>(i) + 0.5f) / static_cast<float>(N), static_cast<float>(y_bits >> 8) * 0x1p-24f};
}

// One binary decision of the hierarchical warp (DESIGN.md §5): the first child with probability
// first / (first + second); u is rescaled into the chosen part so it can be reused below.
// `margin` keeps the smallest |u - split| seen (a near tie a GPU's division may decide otherwise).
bool warp_choose_first(float& u, float first, float second, float& margin) {
  const float p = first / (first + second);
  margin = std::min(margin, std::abs(u - p));
  const bool take_first = u < p;
  u = take_first ? u / p : (u - p) / (1.0f - p);
  u = std::clamp(u, 0.0f, kOneMinusUlp);
  return take_first;
}

std::vector<SamplePoint> reference_samples(const MipPyramid& pdf_pyramid, uint32_t N, uint32_t offset_bits) {
  if (N == 0) throw InputError("the number of VSGLs N must be positive");
  const float qL = pdf_total(pdf_pyramid);
  const MipPyramid& q = pdf_pyramid;
  std::vector<SamplePoint> samples(N);
  for (uint32_t s = 0; s < N; ++s) {
    glm::vec2 u = fibonacci_point(s, N, offset_bits);
    float margin = 1.0f;
    int32_t i = 0;
    int32_t j = 0;  // current node at level k
    for (uint32_t k = q.levels(); k >= 1; --k) {
      const uint32_t c = k - 1;
      const int32_t ci = 2 * i;
      const int32_t cj = 2 * j;
      // Column first, by the sums of the 2x2 children's columns; then the row within it.
      const float left = pdf_weight(q, c, ci, cj) + pdf_weight(q, c, ci, cj + 1);
      const float right = pdf_weight(q, c, ci + 1, cj) + pdf_weight(q, c, ci + 1, cj + 1);
      const int32_t col = warp_choose_first(u.x, left, right, margin) ? ci : ci + 1;
      const float top = pdf_weight(q, c, col, cj);
      const float bottom = pdf_weight(q, c, col, cj + 1);
      const int32_t row = warp_choose_first(u.y, top, bottom, margin) ? cj : cj + 1;
      i = col;
      j = row;
    }
    SamplePoint& out = samples[s];
    out.texel = glm::uvec2(static_cast<uint32_t>(i), static_cast<uint32_t>(j));
    out.x = (glm::vec2(static_cast<float>(i), static_cast<float>(j)) + u) / static_cast<float>(q.size());
    out.pdf = pdf_weight(q, 0, i, j) / qL;
    out.min_margin = margin;
  }
  return samples;
}

// ---- trilinear lookup ----------------------------------------------------------------------

glm::vec4 bilinear(const MipPyramid& layer, glm::vec2 x, uint32_t level) {
  const float sk = static_cast<float>(layer.size() >> level);
  const glm::vec2 u = x * sk - 0.5f;
  const glm::vec2 i0 = glm::floor(u);
  const glm::vec2 f = u - i0;
  const auto ix = static_cast<int32_t>(i0.x);
  const auto iy = static_cast<int32_t>(i0.y);
  return layer.at(level, ix, iy) * ((1.0f - f.x) * (1.0f - f.y)) + layer.at(level, ix + 1, iy) * (f.x * (1.0f - f.y)) +
         layer.at(level, ix, iy + 1) * ((1.0f - f.x) * f.y) + layer.at(level, ix + 1, iy + 1) * (f.x * f.y);
}

glm::vec4 fetch(const MipPyramid& layer, glm::vec2 x, float level) {
  const auto top = static_cast<float>(layer.levels());
  const float l = std::clamp(level, 0.0f, top);
  const float l0 = std::floor(l);
  const auto k0 = static_cast<uint32_t>(l0);
  const uint32_t k1 = std::min(k0 + 1, layer.levels());
  const float t = l - l0;
  return mix_levels(bilinear(layer, x, k0), bilinear(layer, x, k1), t);
}

namespace {

// Bound of one level's bilinear lookup whose weights are off by < delta per axis.
glm::vec4 bilinear_error_bound(const MipPyramid& layer, glm::vec2 x, uint32_t level, float delta) {
  const float sk = static_cast<float>(layer.size() >> level);
  const glm::vec2 i0 = glm::floor(x * sk - 0.5f);
  const auto ix = static_cast<int32_t>(i0.x);
  const auto iy = static_cast<int32_t>(i0.y);
  const glm::vec4 t00 = layer.at(level, ix, iy), t10 = layer.at(level, ix + 1, iy);
  const glm::vec4 t01 = layer.at(level, ix, iy + 1), t11 = layer.at(level, ix + 1, iy + 1);
  const glm::vec4 dx = glm::max(glm::abs(t10 - t00), glm::abs(t11 - t01));
  const glm::vec4 dy = glm::max(glm::abs(t01 - t00), glm::abs(t11 - t10));
  const glm::vec4 dxy = glm::abs(t00 - t10 - t01 + t11);
  return delta * (dx + dy) + delta * delta * dxy;
}

}  // namespace

glm::vec4 fetch_error_bound(const MipPyramid& layer, glm::vec2 x, float level, FilterPrecision precision) {
  const float delta = precision.sub_texel_bits == 0 ? 0.0f : std::ldexp(1.0f, -static_cast<int>(precision.sub_texel_bits));
  const float delta_m = precision.mipmap_bits == 0 ? 0.0f : std::ldexp(1.0f, -static_cast<int>(precision.mipmap_bits));
  const auto top = static_cast<float>(layer.levels());
  const float l = std::clamp(level, 0.0f, top);
  const auto k0 = static_cast<uint32_t>(std::floor(l));
  const uint32_t k1 = std::min(k0 + 1, layer.levels());
  const glm::vec4 b0 = bilinear(layer, x, k0), b1 = bilinear(layer, x, k1);
  const glm::vec4 e0 = bilinear_error_bound(layer, x, k0, delta), e1 = bilinear_error_bound(layer, x, k1, delta);
  const glm::vec4 rounding = 0x1p-20f * (glm::abs(b0) + glm::abs(b1));
  if (k0 == k1) return e0 + rounding;
  return glm::max(e0, e1) + delta_m * (glm::abs(b1 - b0) + e0 + e1) + rounding;
}

double blit_chain_error_ratio(const MipPyramid& chain, FilterPrecision precision) {
  const double delta = precision.sub_texel_bits == 0 ? 0.0 : std::ldexp(1.0, -static_cast<int>(precision.sub_texel_bits));
  double worst = 0;
  for (uint32_t l = 1; l <= chain.levels(); ++l)
    for (uint32_t y = 0; y < chain.square.level_height(l); ++y)
      for (uint32_t x = 0; x < chain.square.level_width(l); ++x) {
        const auto cx = static_cast<int32_t>(2 * x), cy = static_cast<int32_t>(2 * y);
        const glm::vec4 t00 = chain.at(l - 1, cx, cy), t10 = chain.at(l - 1, cx + 1, cy);
        const glm::vec4 t01 = chain.at(l - 1, cx, cy + 1), t11 = chain.at(l - 1, cx + 1, cy + 1);
        const glm::vec4 got = chain.at(l, static_cast<int32_t>(x), static_cast<int32_t>(y));
        for (int c = 0; c < 4; ++c) {
          const double a = t00[c], b = t10[c], d = t01[c], e = t11[c];
          const double mean = (a + b + d + e) * 0.25;
          const double dx = std::max(std::abs(b - a), std::abs(e - d));
          const double dy = std::max(std::abs(d - a), std::abs(e - b));
          const double dxy = std::abs(a - b - d + e);
          const double magnitude = std::abs(a) + std::abs(b) + std::abs(d) + std::abs(e);
          const double bound = delta * (dx + dy) + delta * delta * dxy + 0x1p-20 * magnitude;
          const double err = std::abs(double{got[c]} - mean);
          if (err > 0) worst = std::max(worst, bound > 0 ? err / bound : HUGE_VAL);
        }
      }
  return worst;
}

// ---- level choice and power (DESIGN.md §6.1) ----------------------------------------------------


float tok15_level(float pdf, uint32_t N, float K, const VirtualSquare& square) {
  const auto M = static_cast<float>(square.square_texels());
  const float l = 0.5f * std::log2(K * M / (static_cast<float>(N) * pdf));
  return std::clamp(l, 0.0f, static_cast<float>(square.levels));
}

float modified_kernel_mass(const MipPyramid& pdf_pyramid, glm::vec2 x, float level) {
  const auto M = static_cast<float>(pdf_pyramid.square.square_texels());
  const float p_bar = fetch(pdf_pyramid, x, level).w / pdf_pyramid.top().w;
  return (std::exp2(2.0f * level) / M) * p_bar;
}

float modified_level(const MipPyramid& pdf_pyramid, glm::vec2 x, uint32_t N, float K, uint32_t iterations) {
  const float target = K / static_cast<float>(N);
  if (modified_kernel_mass(pdf_pyramid, x, 0.0f) >= target) return 0.0f;
  float lo = 0.0f;
  auto hi = static_cast<float>(pdf_pyramid.levels());
  for (uint32_t it = 0; it < iterations; ++it) {
    const float mid = 0.5f * (lo + hi);
    if (modified_kernel_mass(pdf_pyramid, x, mid) < target)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5f * (lo + hi);
}

float bisection_tolerance(uint32_t levels, uint32_t iterations) {
  return std::ldexp(static_cast<float>(levels), -static_cast<int>(iterations) - 1);
}

FisKernel fis_kernel(FisVariant variant, const MipPyramid& pdf_pyramid, const SamplePoint& sample,
                     const FisParams& params) {
  FisKernel kernel;
  if (variant == FisVariant::kTok15) {
    kernel.level = tok15_level(sample.pdf, params.vsgl_count, params.K, pdf_pyramid.square);
    kernel.density = sample.pdf;
  } else {
    kernel.level =
        modified_level(pdf_pyramid, sample.x, params.vsgl_count, params.K, params.bisection_iterations);
    kernel.density = fetch(pdf_pyramid, sample.x, kernel.level).w / pdf_pyramid.top().w;
  }
  return kernel;
}

float fis_power_scale(FisVariant variant, const FisKernel& kernel, const FisParams& params,
                      const VirtualSquare& square) {
  const auto M = static_cast<float>(square.square_texels());
  const auto N = static_cast<float>(params.vsgl_count);
  if (variant == FisVariant::kTok15) return M / std::max(N * kernel.density, params.K);
  return M / (N * kernel.density);
}

glm::vec3 fis_power(FisVariant variant, glm::vec3 mean_flux, const FisKernel& kernel, const FisParams& params,
                    const VirtualSquare& square) {
  return fis_power_scale(variant, kernel, params, square) * mean_flux;
}

FisPowerBound fis_power_bound(FisVariant variant, const MomentPyramids& moments, const SamplePoint& sample, float level,
                              const FisParams& params, FilterPrecision precision) {
  const VirtualSquare& sq = moments[0].square;
  const auto M = static_cast<float>(sq.square_texels());
  const auto N = static_cast<float>(params.vsgl_count);
  const float q_top = moments[2].top().w;
  const glm::vec3 f = glm::vec3(fetch(moments[0], sample.x, level));
  const glm::vec3 ef = glm::vec3(fetch_error_bound(moments[0], sample.x, level, precision));
  FisKernel k;
  k.level = level;
  FisPowerBound out;
  if (variant == FisVariant::kTok15) {
    k.density = sample.pdf;
    out.bound = M * ef / std::max(N * k.density, params.K);
  } else {
    k.density = fetch(moments[2], sample.x, level).w / q_top;
    const float ep = fetch_error_bound(moments[2], sample.x, level, precision).w / q_top;
    out.bound = M / (N * k.density) * (ef + glm::abs(f) * (ep / k.density));
  }
  out.expected = fis_power(variant, f, k, params, sq);
  return out;
}

// ---- the generator -------------------------------------------------------------------------

std::vector<VsglRecord> reference_fis(const MomentPyramids& moments, FisVariant variant, const FisParams& params) {
  const char* name = fis_variant_name(variant);
  if (params.vsgl_count == 0) throw InputError(std::string(name) + ": the number of VSGLs N must be positive");
  if (!(params.K > 0.0f) || !std::isfinite(params.K))
    throw InputError(std::string(name) + ": K must be positive and finite, got " + std::to_string(params.K));
  const VirtualSquare& sq = moments[0].square;
  for (const MipPyramid& m : moments) {
    if (m.square.width != sq.width || m.square.height != sq.height || m.texels.size() != sq.total_texels())
      throw InputError(std::string(name) + ": the moment pyramids differ in size");
  }
  const MipPyramid& pdf = moments[2];
  pdf_total(pdf);  // throws for an all-zero PDF before the sample-count check below reads 0
  const std::size_t level0 = sq.level_texels(0);
  const auto sampleable = static_cast<std::size_t>(std::count_if(
      pdf.texels.begin(), pdf.texels.begin() + static_cast<std::ptrdiff_t>(level0),
      [](const glm::vec4& t) { return t.w > 0.0f; }));
  if (params.vsgl_count > sampleable)
    throw InputError(std::string(name) + ": N = " + std::to_string(params.vsgl_count) +
                     " exceeds the texels of nonzero PDF (" + std::to_string(sampleable) + ")");

  const std::vector<SamplePoint> samples = reference_samples(pdf, params.vsgl_count, params.offset_bits);
  std::vector<VsglRecord> out(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const SamplePoint& s = samples[i];
    const FisKernel kernel = fis_kernel(variant, pdf, s, params);
    const TexelMoments m{fetch(moments[0], s.x, kernel.level), fetch(moments[1], s.x, kernel.level),
                         fetch(moments[2], s.x, kernel.level), fetch(moments[3], s.x, kernel.level),
                         fetch(moments[4], s.x, kernel.level)};
    out[i] =
        vsgl_from_moments(m, fis_power_scale(variant, kernel, params, sq), kernel.level, s.x, kernel.density, 0.0f);
  }
  return out;
}

}  // namespace vsgl
