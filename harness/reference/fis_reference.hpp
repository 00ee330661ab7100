#pragma once
// The CPU reference of the FIS generators `fis_tok15` and `fis_modified` (DESIGN.md §4-§7): the moment
// layers ("additional"), their mip pyramids ("mipmapping"), the stratified hierarchical sampler
// and the level choice and power of each variant ("filtered_sampling").
//
// float32 throughout, with the GPU kernels' operation order (kernels/CONVENTIONS.md): the
// pyramid and the sampler's texel choices match the GPU bit for bit where its division is
// correctly rounded (lavapipe); levels and powers involve log2/exp2 and trilinear fetches and
// match to float rounding.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "harness/capture/capture.hpp"
#include "harness/math/fis_params.hpp"
#include "harness/math/virtual_square.hpp"
#include "harness/math/vsgl_math.hpp"

namespace vsgl {

// A mip pyramid of one vec4 layer over the virtual square (DESIGN.md §4), in the GPU's flat layout.
struct MipPyramid {
  VirtualSquare square;
  std::vector<glm::vec4> texels;  // square.total_texels() entries, level after level, row-major

  // Builds levels 1..L from level 0 (W x H texels, row-major): a level-(l+1) texel is
  // (c00 + c10 + c01 + c11) * 0.25 of its children, in that order, children outside level l's
  // extent reading as zero. Throws InputError when level0 has not W * H entries.
  static MipPyramid build(const std::vector<glm::vec4>& level0, uint32_t w, uint32_t h);

  uint32_t levels() const { return square.levels; }  // L
  uint32_t size() const { return square.size; }      // S
  // Texel (x, y) of `level`; zero outside the level's in-bounds extent (and beyond the square).
  glm::vec4 at(uint32_t level, int32_t x, int32_t y) const;
  // The level-L texel: the mean over the whole virtual square.
  glm::vec4 top() const { return texels.back(); }
};

// The moment layers of a view (DESIGN.md §4: texel_moments()'s m0..m4), and their pyramids; the
// PDF q is layer 2's .w.
inline constexpr std::size_t kMomentLayerCount = 5;
inline constexpr std::size_t kPdfLayer = 2;
using MomentLayers = std::array<std::vector<glm::vec4>, kMomentLayerCount>;
using MomentPyramids = std::array<MipPyramid, kMomentLayerCount>;

// The "additional" pass on the CPU: layers M0..M4 of every texel of a view (DESIGN.md §4), each
// W * H vec4s, through texel_moments(). source_pos: the spot light (RSM) or the camera (G-buffer).
// Throws InputError when the view's planes do not hold W * H texels.
MomentLayers reference_moments(const ViewImage& view, glm::vec3 source_pos);
// The mip pyramid of every layer (MipPyramid::build).
MomentPyramids build_moment_pyramids(const MomentLayers& level0, uint32_t w, uint32_t h);

// Kernel centre u_i of the Fibonacci lattice (DESIGN.md §5):
//   u.x = (i + 0.5) / N,  u.y = ((i * 2654435769 + offset_bits) mod 2^32 >> 8) * 2^-24.
glm::vec2 fibonacci_point(uint32_t i, uint32_t N, uint32_t offset_bits);

// One sample of the hierarchical warping.
struct SamplePoint {
  glm::uvec2 texel{0u};  // chosen level-0 texel
  glm::vec2 x{0.0f};     // kernel centre in [0,1]^2 of the square
  float pdf = 0.0f;      // p(x) = q0(texel) / qL
  // Smallest |u - split| over the path's decisions (1 when there were none, L = 0): a GPU whose
  // division is not correctly rounded may pick another child only where this is tiny.
  float min_margin = 1.0f;
};

// N kernel centres warped through the PDF pyramid q (the .w channel: the M2 layer's pyramid).
// Throws InputError for N = 0 and for a PDF that is zero (or not finite) over the whole square.
std::vector<SamplePoint> reference_samples(const MipPyramid& pdf_pyramid, uint32_t N, uint32_t offset_bits);

// Fractional-level lookup (DESIGN.md §4): bilinear within a level (taps outside the extent read zero),
// linear between floor(l) and min(floor(l) + 1, L). l is clamped to [0, L].
glm::vec4 bilinear(const MipPyramid& layer, glm::vec2 x, uint32_t level);
glm::vec4 fetch(const MipPyramid& layer, glm::vec2 x, float level);

// How finely a device's sampler resolves a trilinear lookup (DESIGN.md §6.1a): each bilinear weight
// is a multiple of 2^-sub_texel_bits, the level fraction a multiple of 2^-mipmap_bits
// (VkPhysicalDeviceLimits::subTexelPrecisionBits / mipmapPrecisionBits; 0: exact).
struct FilterPrecision {
  uint32_t sub_texel_bits = 0;
  uint32_t mipmap_bits = 0;
};
// A bound, per component, on |device lookup - fetch(layer, x, level)| for any device whose
// weights are fetch()'s rounded or truncated to `precision` (each weight off by < one step):
// per level delta (Dx + Dy) + delta^2 Dxy over the 2x2 taps' differences, between levels
// max(e0, e1) + delta_m (|B1 - B0| + e0 + e1), plus float rounding (2^-20 of the magnitude).
glm::vec4 fetch_error_bound(const MipPyramid& layer, glm::vec2 x, float level, FilterPrecision precision);

// A mip chain built by a linear 2:1 blit (DESIGN.md §6.1a) against the mean of its own children, level
// by level: the blit's sample lands between the four children only to `precision` (each weight
// 1/2 off by < 2^-sub_texel_bits), so each texel may differ from the mean by delta (Dx + Dy) +
// delta^2 Dxy of its children plus float rounding (2^-20 of their magnitude). Returns the worst
// |texel - mean| / that bound over every level and component (<= 1: within the bound).
double blit_chain_error_ratio(const MipPyramid& chain, FilterPrecision precision);


// Eq. 1 of the 2016 paper: l = clamp(0.5 log2(K M / (N p)), 0, L).
float tok15_level(float pdf, uint32_t N, float K, const VirtualSquare& square);
// The modified kernel's share of the probability, g(l) = (4^l / M) * p_bar(x, l) (Eq. 3).
float modified_kernel_mass(const MipPyramid& pdf_pyramid, glm::vec2 x, float level);
// Eq. 3 with K: the level where g(l) = K / N, by bisection on [0, L]; 0 when g(0) >= K / N.
float modified_level(const MipPyramid& pdf_pyramid, glm::vec2 x, uint32_t N, float K, uint32_t iterations);
// Largest |l - l_exact| the bisection leaves: L / 2^(iterations + 1).
float bisection_tolerance(uint32_t levels, uint32_t iterations);

// What distinguishes the two generators (DESIGN.md §6.1: "about ten lines"): the level and the density
// that divides the power.
struct FisKernel {
  float level = 0.0f;
  float density = 0.0f;  // p(x_i) (Tok15) or p_bar(x_i, l_i) (modified); recorded in the VSGL
};
FisKernel fis_kernel(FisVariant variant, const MipPyramid& pdf_pyramid, const SamplePoint& sample,
                     const FisParams& params);
// The factor of the filtered mean flux f_bar in the power: Tok15 M / max(N p, K) (Eq. 4 scaled by
// M), modified M / (N p_bar) (Eq. 5); the GPU forms the power in this order (scale, then times f_bar).
float fis_power_scale(FisVariant variant, const FisKernel& kernel, const FisParams& params,
                      const VirtualSquare& square);
// fis_power_scale() * mean_flux.
glm::vec3 fis_power(FisVariant variant, glm::vec3 mean_flux, const FisKernel& kernel, const FisParams& params,
                    const VirtualSquare& square);

// What a device's VSGL at `level` (the level the device chose) for `sample` should carry: the
// power of the fetches from the CPU's pyramids of M0 (fis_power), and per component how
// far a device may be from it: the fetches' filter error (fetch_error_bound at `precision`)
// carried through Eq. 4 (Tok15: M ef / max(N p, K)) or, to first order, Eq. 5 (modified:
// M / (N p_bar) (ef + |f| ep / p_bar), ep the error of p_bar's own fetch).
struct FisPowerBound {
  glm::vec3 expected{0.0f};
  glm::vec3 bound{0.0f};
};
FisPowerBound fis_power_bound(FisVariant variant, const MomentPyramids& moments, const SamplePoint& sample, float level,
                              const FisParams& params, FilterPrecision precision);

// The whole generator: N VSGLs from the pyramids of M0 ... M4 (the PDF is M2's .w). Throws
// InputError for N = 0, N larger than the texels of nonzero PDF, K <= 0 or not finite, pyramids
// of different sizes, or an all-zero PDF.
std::vector<VsglRecord> reference_fis(const MomentPyramids& moments, FisVariant variant, const FisParams& params);

}  // namespace vsgl
