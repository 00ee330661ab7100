#pragma once
// Where a FIS generator's total power comes from (DESIGN.md §11a, "Energy explained").
//
// A FIS VSGL's power is Phi_i = M f_bar(x_i, l_i) / D_i (Eq. 4: D_i = max(N p(x_i), K); Eq. 5:
// D_i = N p_bar(x_i, l_i)), and f_bar is the trilinear mean sum_t w_i(t) f(t) over level-0 texels
// (quality_metrics.hpp). So the total power is exactly sum_t f(t) c(t) with
//   c(t) = sum_i M w_i(t) / D_i,
// the number of times texel t's flux enters it. Splitting the texels by their expected number of
// kernel centres e(t) = N q(t) / sum q (0 off the PDF's support) shows which flux is counted
// once, which is lost (c < 1) and which is counted twice.
//
// Two identities make it a check as well as an explanation:
//   - sum_t q(t) c(t) / sum_t q(t) = (1/N) sum_i p_bar_i / (D_i / N): exactly 1 for Eq. 5 whatever
//     the levels (the power of a flux proportional to the PDF is conserved), and for Eq. 4 the mean
//     of p_bar(x_i, l_i) / max(p(x_i), K/N), its over-count of such a flux;
//   - sum_t f(t) c(t) is the VSGLs' power summed, up to the device's filtering (§6.1a).
// A modified FIS whose pdf_weighted_count is not 1 divides by a density other than the one its
// kernel filters: a defect, not a property of Eq. 5.
#include <array>
#include <cstdint>
#include <vector>

#include "harness/math/fis_params.hpp"
#include "harness/math/vsgl_math.hpp"
#include "harness/reference/fis_reference.hpp"

namespace vsgl {

// Texel classes by expected kernel centres e(t): [0] PDF 0 (off the support), then e in
// (0, 1e-3), [1e-3, 1e-2), [1e-2, 1e-1), [1e-1, inf).
inline constexpr std::array<double, 3> kExpectedCentreBounds = {1e-3, 1e-2, 1e-1};
inline constexpr std::size_t kFluxClasses = kExpectedCentreBounds.size() + 2;
// A kernel is "oversized" when it holds more than this many times its stratum's probability
// (a(l_i) p_bar(x_i, l_i) N / K, Eq. 3's left side over its target): the kernels Tok15 sizes from
// a centre whose PDF is far below its neighbourhood's.
inline constexpr double kOversizedMass = 2.0;

// The class of a texel with PDF weight q, for N kernels and a PDF summing to q_sum over the view.
std::size_t flux_class(double q, double q_sum, uint32_t N);

// How a view's flux is spread over the classes (the same for every generator of the view).
struct FluxByPdf {
  std::array<uint64_t, kFluxClasses> texels{};    // texels with positive flux
  std::array<double, kFluxClasses> flux_share{};  // sum f over the class / the view's flux
};

struct FluxOrigin {
  FluxByPdf view;
  // sum over the class of f(t) c(t) / the view's flux; the classes sum to attributed_power_ratio.
  std::array<double, kFluxClasses> gathered{};
  // ... of it, the part that oversized kernels (kOversizedMass) carry.
  std::array<double, kFluxClasses> gathered_by_oversized{};
  double attributed_power_ratio = 0;  // sum_t f c / sum_t f
  double pdf_weighted_count = 0;      // sum_t q c / sum_t q (1 for Eq. 5)
  double oversized_kernels = 0;       // share of the kernels that are oversized
};

// `texel_flux`: f per level-0 texel of the view (W x H, row-major, Phi.r + Phi.g + Phi.b);
// `pdf`: the view's PDF pyramid (M2's .w); `kernels`: the generator's N records (level, centre and
// the density divided by, DESIGN.md §7). Throws InputError for no kernels, a record without a FIS
// level, sizes that differ, a zero PDF or zero flux.
FluxOrigin flux_origin(const std::vector<VsglRecord>& kernels, FisVariant variant, const std::vector<float>& texel_flux,
                       const MipPyramid& pdf, float K);

// The view's split alone (k-means clusters every texel with flux once, so it has no other).
FluxByPdf flux_by_pdf(const std::vector<float>& texel_flux, const MipPyramid& pdf, uint32_t N);

// f per level-0 texel from a view's M0 layer (reference_moments()[0]): Phi.r + Phi.g + Phi.b.
std::vector<float> texel_flux(const std::vector<glm::vec4>& m0);

}  // namespace vsgl
