// Where a FIS generator's power comes from (harness/quality/flux_origin.hpp, DESIGN.md §11a) on
// synthetic PDFs with known answers: a PDF that is 0 on half the texels, which carry a known share
// of the flux, and kernels whose footprints are known blocks of texels; then the identities that
// make it a check on the generators: the attributed power is the VSGLs' power, and Eq. 5 conserves
// the power of a flux proportional to the PDF (PDF-weighted count exactly 1), Eq. 4 does not.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "harness/core/error.hpp"
#include "harness/quality/flux_origin.hpp"
#include "harness/quality/quality_metrics.hpp"
#include "harness/reference/fis_reference.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

using test::layer;

// 8 x 8 texels (M = 64, L = 3): PDF 0 on the left half (x < 4), 1 on the right; flux 3 per texel
// on the left and 1 on the right, so the PDF's zero half holds 96 / 128 = 0.75 of the flux.
constexpr uint32_t kSide = 8;
MipPyramid half_zero_pdf() {
  return MipPyramid::build(
      layer(kSide, kSide, [](uint32_t x, uint32_t) { return glm::vec4(0, 0, 0, x < 4 ? 0.0f : 1.0f); }), kSide, kSide);
}
std::vector<float> half_zero_flux() {
  std::vector<float> f;
  for (uint32_t y = 0; y < kSide; ++y)
    for (uint32_t x = 0; x < kSide; ++x) f.push_back(x < 4 ? 3.0f : 1.0f);
  return f;
}

VsglRecord kernel(float x, float y, float level, float density) {
  VsglRecord v;
  v.center_pdf = glm::vec4(x, y, density, 0.0f);
  v.axis_level = glm::vec4(0.0f, 0.0f, 1.0f, level);
  return v;
}

double sum(const std::array<double, kFluxClasses>& a) {
  double s = 0;
  for (double v : a) s += v;
  return s;
}

TEST(FluxOrigin, ClassesByExpectedKernelCentres) {
  // e = N q / sum q: 0 for q = 0, then the bounds 1e-3, 1e-2, 1e-1 start classes 2, 3, 4.
  EXPECT_EQ(flux_class(0.0, 10.0, 100), 0u);
  EXPECT_EQ(flux_class(1e-5, 10.0, 100), 1u);  // e = 1e-4
  EXPECT_EQ(flux_class(1e-4, 10.0, 100), 2u);  // e = 1e-3
  EXPECT_EQ(flux_class(5e-3, 10.0, 100), 3u);  // e = 0.05
  EXPECT_EQ(flux_class(1.0, 10.0, 100), 4u);   // e = 10
}

TEST(FluxOrigin, TheViewsFluxSplitsAtTheSupport) {
  const FluxByPdf f = flux_by_pdf(half_zero_flux(), half_zero_pdf(), 2);
  // Right half: e = 2 * 1 / 32 = 0.0625, class [1e-2, 1e-1).
  EXPECT_EQ(f.texels[0], 32u);
  EXPECT_EQ(f.texels[3], 32u);
  EXPECT_DOUBLE_EQ(f.flux_share[0], 0.75);
  EXPECT_DOUBLE_EQ(f.flux_share[3], 0.25);
  EXPECT_DOUBLE_EQ(sum(f.flux_share), 1.0);
}

TEST(FluxOrigin, KnownFootprintsGatherKnownFlux) {
  // Two level-2 kernels (blocks of 4 x 4 texels), N = 2, p = q / mean q = 2 on the support.
  //  a: centred on the top-right block (all support): p_bar = 2, D = N p_bar = 4, M / D = 16, each
  //     of its 16 texels weighted 1/16: c = 1 there.
  //  b: centred on the seam between the bottom-left (PDF 0) and bottom-right blocks: half its
  //     weight on each, p_bar = 1, D = 2, M / D = 32: c = 32 * 0.5 / 16 = 1 on all 32 texels.
  // So the zero half gives 16 texels * 3 = 48 of 128, the support 32 * 1 = 32 of 128.
  const std::vector<VsglRecord> modified{kernel(0.75f, 0.25f, 2.0f, 2.0f), kernel(0.5f, 0.75f, 2.0f, 1.0f)};
  const FluxOrigin m = flux_origin(modified, FisVariant::kModified, half_zero_flux(), half_zero_pdf(), 1.0f);
  EXPECT_DOUBLE_EQ(m.gathered[0], 48.0 / 128.0);
  EXPECT_DOUBLE_EQ(m.gathered[3], 32.0 / 128.0);
  EXPECT_DOUBLE_EQ(m.attributed_power_ratio, 80.0 / 128.0);
  EXPECT_DOUBLE_EQ(sum(m.gathered), m.attributed_power_ratio);
  // Eq. 5: every kernel divides by the density its own footprint holds, so a flux proportional to
  // the PDF is counted exactly once.
  EXPECT_DOUBLE_EQ(m.pdf_weighted_count, 1.0);
  // Each kernel holds (16 / 64) p_bar = 0.5 and 0.25 of the probability against K / N = 0.5.
  EXPECT_EQ(m.oversized_kernels, 0.0);
  EXPECT_EQ(sum(m.gathered_by_oversized), 0.0);

  // Eq. 4 divides b's power by the density at its centre (2, in the support), not its
  // footprint's (1): D = max(N p, K) = 4, c = 0.5 under b, and the PDF-weighted count is the mean
  // of p_bar / p over the kernels, (1 + 0.5) / 2.
  const std::vector<VsglRecord> tok15{kernel(0.75f, 0.25f, 2.0f, 2.0f), kernel(0.5f, 0.75f, 2.0f, 2.0f)};
  const FluxOrigin t = flux_origin(tok15, FisVariant::kTok15, half_zero_flux(), half_zero_pdf(), 1.0f);
  EXPECT_DOUBLE_EQ(t.gathered[0], 24.0 / 128.0);
  EXPECT_DOUBLE_EQ(t.gathered[3], 24.0 / 128.0);
  EXPECT_DOUBLE_EQ(t.pdf_weighted_count, 0.75);
}

TEST(FluxOrigin, AnOversizedKernelIsCountedApart) {
  // One level-3 kernel covers the whole square; with K = 1/4 its mass 1 is 4 times K / N.
  const std::vector<VsglRecord> k{kernel(0.5f, 0.5f, 3.0f, 1.0f)};
  const FluxOrigin m = flux_origin(k, FisVariant::kModified, half_zero_flux(), half_zero_pdf(), 0.25f);
  EXPECT_EQ(m.oversized_kernels, 1.0);
  EXPECT_DOUBLE_EQ(m.gathered[0], 0.75);
  EXPECT_DOUBLE_EQ(m.gathered[3], 0.25);
  EXPECT_EQ(m.gathered_by_oversized, m.gathered);
  EXPECT_DOUBLE_EQ(m.attributed_power_ratio, 1.0);
  // Tok15 with the centre's p = 2: D = max(1 * 2, 1/4) = 2, half the flux of every texel.
  const std::vector<VsglRecord> t{kernel(0.5f, 0.5f, 3.0f, 2.0f)};
  EXPECT_DOUBLE_EQ(flux_origin(t, FisVariant::kTok15, half_zero_flux(), half_zero_pdf(), 0.25f).attributed_power_ratio,
                   0.5);
}

// A 32 x 32 view with a PDF that is 0 on a band and varies elsewhere, flux that does not follow it.
MomentPyramids uneven_view() {
  constexpr uint32_t s = 32;
  const auto q = [](uint32_t x, uint32_t y) {
    if (x >= 10 && x < 18) return 0.0f;
    return static_cast<float>((x * 7 + y * 13) % 11) * 0.1f + (y < 8 ? 4.0f : 0.02f);
  };
  const auto m0 = layer(s, s, [](uint32_t x, uint32_t y) {
    const float f = 0.5f + static_cast<float>((x * 5 + y * 3) % 7);
    return glm::vec4(f, 0.5f * f, 0.25f * f, 1.75f * f);
  });
  const auto m1 = layer(s, s, [](uint32_t x, uint32_t y) {
    const glm::vec3 P(static_cast<float>(x), 0.0f, static_cast<float>(y));
    return glm::vec4(P, glm::dot(P, P));
  });
  const auto m2 = layer(s, s, [&](uint32_t x, uint32_t y) { return glm::vec4(0.0f, 1.75f, 0.0f, q(x, y)); });
  const auto none = layer(s, s, [](uint32_t, uint32_t) { return glm::vec4(0.0f); });  // no specular part
  return {MipPyramid::build(m0, s, s), MipPyramid::build(m1, s, s), MipPyramid::build(m2, s, s),
          MipPyramid::build(none, s, s), MipPyramid::build(none, s, s)};
}

TEST(FluxOrigin, AttributionSumsToTheGeneratorsPowerAndEq5ConservesThePdf) {
  const auto moments = uneven_view();
  std::vector<float> flux;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const glm::vec4 m = moments[0].at(0, static_cast<int32_t>(x), static_cast<int32_t>(y));
      flux.push_back(m.r + m.g + m.b);
    }
  double total = 0;
  for (float f : flux) total += static_cast<double>(f);
  for (FisVariant variant : {FisVariant::kTok15, FisVariant::kModified}) {
    SCOPED_TRACE(fis_variant_name(variant));
    FisParams params;
    params.vsgl_count = 48;
    params.K = 1.0f;
    const std::vector<VsglRecord> vsgls = reference_fis(moments, variant, params);
    double power = 0;
    for (const VsglRecord& v : vsgls) power += static_cast<double>(v.power().r + v.power().g + v.power().b);
    const FluxOrigin o = flux_origin(vsgls, variant, flux, moments[2], params.K);
    // sum_t f c is the VSGLs' power, to float rounding of the powers and the trilinear weights.
    EXPECT_NEAR(o.attributed_power_ratio, power / total, 1e-5 * power / total);
    EXPECT_NEAR(sum(o.gathered), o.attributed_power_ratio, 1e-12);
    if (variant == FisVariant::kModified) {
      EXPECT_NEAR(o.pdf_weighted_count, 1.0, 1e-5);  // would catch a power divided by another density
    }
  }
}

TEST(FluxOrigin, RefusesWhatItCannotAttribute) {
  EXPECT_THROW(flux_origin({}, FisVariant::kModified, half_zero_flux(), half_zero_pdf(), 1.0f), InputError);
  EXPECT_THROW(flux_origin({kernel(0.5f, 0.5f, 1.0f, 1.0f)}, FisVariant::kModified, std::vector<float>(10, 1.0f),
                           half_zero_pdf(), 1.0f),
               InputError);
  EXPECT_THROW(
      flux_origin({kernel(0.5f, 0.5f, -1.0f, 1.0f)}, FisVariant::kModified, half_zero_flux(), half_zero_pdf(), 1.0f),
      InputError);
  EXPECT_THROW(
      flux_origin({kernel(0.5f, 0.5f, 1.0f, 0.0f)}, FisVariant::kModified, half_zero_flux(), half_zero_pdf(), 1.0f),
      InputError);
  EXPECT_THROW(flux_by_pdf(std::vector<float>(64, 0.0f), half_zero_pdf(), 1), InputError);
}

}  // namespace
}  // namespace vsgl
