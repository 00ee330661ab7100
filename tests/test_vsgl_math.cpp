// The VSGL maths on the CPU (harness/math/vsgl_math.hpp, twin of kernels/include/vsgl_math.glsl and
// sg_eval.glsl): lobe statistics (DESIGN.md §7), VSGLs from moments, and SG evaluation with its
// point-light limit (DESIGN.md §8, §11).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "harness/math/vsgl_math.hpp"

namespace vsgl {
namespace {

constexpr double kPiD = 3.14159265358979323846;

glm::dvec3 to_d(glm::vec3 v) { return glm::dvec3(v); }

// Exact A(lambda) in double: coth - 1/lambda, or its series where that cancels.
double exact_mean_length(double lambda) {
  if (lambda < 1e-2) return lambda / 3.0 - lambda * lambda * lambda / 45.0;
  return 1.0 / std::tanh(lambda) - 1.0 / lambda;
}

double sg_d(glm::dvec3 w, glm::dvec3 a, double s) { return std::exp(s * (glm::dot(w, a) - 1.0)); }

// Midpoint quadrature over S^2 in (z, phi) about the axis `pole` (put the sharpest lobe there).
double sphere_integral(const std::function<double(glm::dvec3)>& f, glm::dvec3 pole, int nz = 2000, int nphi = 400) {
  const glm::dvec3 e3 = glm::normalize(pole);
  const glm::dvec3 helper = std::abs(e3.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(helper, e3));
  const glm::dvec3 e2 = glm::cross(e3, e1);
  double sum = 0.0;
  for (int a = 0; a < nz; ++a) {
    const double z = -1.0 + (a + 0.5) * 2.0 / nz;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int b = 0; b < nphi; ++b) {
      const double phi = (b + 0.5) * 2.0 * kPiD / nphi;
      sum += f(rho * std::cos(phi) * e1 + rho * std::sin(phi) * e2 + z * e3);
    }
  }
  return sum * (2.0 / nz) * (2.0 * kPiD / nphi);
}

// ---- lobe statistics ------------------------------------------------------------------------

TEST(VsglMath, MeanResultantLengthMatchesExactFormulaOverItsRange) {
  // Every branch (series, coth, asymptote) to float accuracy: relative error <= 2e-6.
  for (double lambda = 1e-5; lambda < 2e4; lambda *= 1.07) {
    const float a = mean_resultant_length(static_cast<float>(lambda));
    const double exact = exact_mean_length(static_cast<double>(static_cast<float>(lambda)));
    EXPECT_NEAR(a, exact, 2e-6 * exact) << "lambda " << lambda;
  }
  EXPECT_EQ(mean_resultant_length(0.0f), 0.0f);
  // Continuous and increasing across the branch points.
  for (float edge : {1e-3f, 0.5f, 20.0f}) {
    const float below = std::nextafter(edge, 0.0f);
    EXPECT_NEAR(mean_resultant_length(below), mean_resultant_length(edge), 2e-6f * mean_resultant_length(edge));
    EXPECT_LE(mean_resultant_length(below), mean_resultant_length(edge) * (1.0f + 1e-6f));
  }
}

TEST(VsglMath, BanerjeeIsApproximatelyTheInverseOfMeanResultantLength) {
  // Banerjee's approximation is within 5% of the inverse (worst near lambda ~ 10).
  for (float lambda : {0.5f, 2.29f, 10.0f, 100.0f}) {
    const float back = banerjee_sharpness(mean_resultant_length(lambda));
    EXPECT_NEAR(back, lambda, 0.05f * lambda) << "lambda " << lambda;
  }
  EXPECT_EQ(banerjee_sharpness(0.0f), 0.0f);
  EXPECT_EQ(banerjee_sharpness(-0.5f), 0.0f);
  // r is clamped to 0.9999 (lambda ~= 1e4), lambda to [0, 1e4].
  EXPECT_EQ(banerjee_sharpness(1.0f), banerjee_sharpness(kMaxMeanLength));
  EXPECT_EQ(banerjee_sharpness(2.0f), banerjee_sharpness(kMaxMeanLength));
  EXPECT_LE(banerjee_sharpness(kMaxMeanLength), kMaxSharpness);
  EXPECT_GT(banerjee_sharpness(kMaxMeanLength), 0.999f * kMaxSharpness);
  EXPECT_GT(banerjee_sharpness(0.999f), 900.0f);
}

TEST(VsglMath, SpecularDirectionIsTheMirrorLobesMeanVector) {
  const glm::vec3 P(1.0f, 2.0f, 3.0f);
  const glm::vec3 N(0.0f, 1.0f, 0.0f);
  // Lit from 45 degrees: along the mirror direction, length A(lambda_s) with
  // lambda_s = (2 / alpha^2) / (4 cos 45).
  const glm::vec3 src = P + glm::vec3(-3.0f, 3.0f, 0.0f);
  const float alpha = 0.3f;
  const glm::vec3 s = texel_specular_direction(P, N, alpha, src);
  const float lambda_s = (2.0f / (alpha * alpha)) / (4.0f * std::sqrt(0.5f));
  const glm::vec3 mirror = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
  EXPECT_NEAR(glm::length(s), mean_resultant_length(lambda_s), 1e-6f);
  EXPECT_NEAR(glm::dot(glm::normalize(s), mirror), 1.0f, 1e-6f);
  // A source on the texel: finite (the normal stands in for the direction).
  const glm::vec3 on = texel_specular_direction(P, N, alpha, P);
  EXPECT_TRUE(std::isfinite(on.x) && std::isfinite(on.y) && std::isfinite(on.z));
  // Very smooth, grazing: lambda_s clamps at 1e4 and the length stays below 1.
  const glm::vec3 g = texel_specular_direction(P, N, 0.0f, P + glm::vec3(10, 0, 0));
  EXPECT_NEAR(glm::length(g), mean_resultant_length(kMaxSharpness), 1e-6f);
}

TEST(VsglMath, TexelMomentsOfBothViews) {
  // Tok15 §3.2's RSM: positions and squared norms, normals, diffuse and specular coefficients, the
  // specular lobe's averaged direction, and the PDF (DESIGN.md §4).
  const glm::vec3 P(0.5f, -1.0f, 2.0f), N(0.0f, 0.0f, 1.0f), kd(0.2f, 0.4f, 0.6f), ks(0.1f, 0.1f, 0.1f);
  const glm::vec3 src(0.0f, 0.0f, 10.0f);
  const TexelMoments light = texel_moments(true, P, N, kd, ks, 0.4f, 0.7f, src, false);
  const glm::vec3 phi = kd + ks;
  const float w_light = phi.r + phi.g + phi.b;
  const float s = ks.r + ks.g + ks.b;
  EXPECT_EQ(light.m0, glm::vec4(phi, w_light));
  EXPECT_EQ(light.m1, glm::vec4(w_light * P, w_light * glm::dot(P, P)));
  EXPECT_EQ(light.m2, glm::vec4(w_light * N, 0.7f));
  EXPECT_EQ(light.m3, glm::vec4(ks, 0.0f));
  EXPECT_EQ(light.m4, glm::vec4(s * texel_specular_direction(P, N, 0.4f, src), 0.0f));

  const TexelMoments cam = texel_moments(true, P, N, kd, ks, 0.4f, 0.3f, src, true);
  const float w_cam = 0.2126f * phi.r + 0.7152f * phi.g + 0.0722f * phi.b;
  EXPECT_FLOAT_EQ(cam.m0.w, w_cam);
  EXPECT_FLOAT_EQ(cam.m1.x, w_cam * P.x);
  EXPECT_FLOAT_EQ(cam.m2.z, w_cam);
  EXPECT_FLOAT_EQ(cam.m2.w, 0.3f);

  // No specular part: no lobe direction (not a zero-length vector averaged into the lobe).
  const TexelMoments matte = texel_moments(true, P, N, kd, glm::vec3(0.0f), 0.4f, 0.7f, src, false);
  EXPECT_EQ(matte.m3, glm::vec4(0.0f));
  EXPECT_EQ(matte.m4, glm::vec4(0.0f));

  const TexelMoments invalid = texel_moments(false, P, N, kd, ks, 0.4f, 0.7f, src, false);
  for (const glm::vec4& layer : {invalid.m0, invalid.m1, invalid.m2, invalid.m3, invalid.m4})
    EXPECT_EQ(layer, glm::vec4(0.0f));
}

// ---- VSGL from moments ----------------------------------------------------------------------

TEST(VsglMath, SingleTexelGivesItsPositionNormalAndTheMinimumRadius) {
  // Dyadic values: every product is exact in float, so the variance is exactly zero before the
  // clamp and r^2 = 2 eps.
  const glm::vec3 P(0.5f, -1.25f, 2.0f), N(0.0f, 1.0f, 0.0f);
  const TexelMoments m = texel_moments(true, P, N, glm::vec3(0.5f, 0.25f, 0.25f), glm::vec3(0.0f), 0.5f, 1.0f,
                                       glm::vec3(0.0f, 8.0f, 0.0f), false);
  const VsglRecord v = vsgl_from_moments(m, 2.0f, 2.5f, glm::vec2(0.25f, 0.75f), 0.5f, 0.0f);
  EXPECT_EQ(v.mu(), P);
  EXPECT_EQ(v.sigma2(), kMinVariance);
  EXPECT_EQ(v.normal(), N);
  EXPECT_EQ(v.normal_length.w, 1.0f);
  // No specular part: a zero-sharpness lobe along the normal and no specular power.
  EXPECT_EQ(v.axis(), N);
  EXPECT_EQ(v.sharpness(), 0.0f);
  EXPECT_EQ(v.power(), glm::vec3(1.0f, 0.5f, 0.5f));
  EXPECT_EQ(v.specular(), glm::vec3(0.0f));
  EXPECT_EQ(v.level(), 2.5f);
  EXPECT_EQ(v.center_pdf, glm::vec4(0.25f, 0.75f, 0.5f, 0.0f));

  // A specular texel: the lobe restored from the averaged direction (Banerjee of A(lambda_s)).
  const TexelMoments g = texel_moments(true, P, N, glm::vec3(0.25f), glm::vec3(0.5f), 0.25f, 1.0f,
                                       P + glm::vec3(-4.0f, 4.0f, 0.0f), false);
  const VsglRecord vg = vsgl_from_moments(g, 1.0f, 0.0f, glm::vec2(0.0f), 1.0f, 0.0f);
  const float lambda_s = (2.0f / 0.0625f) / (4.0f * std::sqrt(0.5f));
  EXPECT_NEAR(vg.sharpness(), lambda_s, 0.05f * lambda_s);  // Banerjee's inverse is within 5 %
  EXPECT_NEAR(glm::dot(vg.axis(), glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f))), 1.0f, 1e-6f);
  EXPECT_EQ(vg.specular(), glm::vec3(0.5f));
  EXPECT_EQ(vg.power(), glm::vec3(0.75f));

  // General values: the cancellation in E|P|^2 - |mu|^2 leaves at most a few ulps of |P|^2.
  const glm::vec3 Q(1.37f, -2.71f, 0.33f);
  const TexelMoments mq = texel_moments(true, Q, N, glm::vec3(0.31f, 0.17f, 0.05f), glm::vec3(0.02f), 0.5f, 1.0f,
                                        glm::vec3(0.0f, 8.0f, 0.0f), false);
  const VsglRecord vq = vsgl_from_moments(mq, 1.0f, 0.0f, glm::vec2(0.0f), 1.0f, 0.0f);
  EXPECT_NEAR(glm::length(vq.mu() - Q), 0.0f, 4e-7f * glm::length(Q));
  EXPECT_GE(vq.sigma2(), kMinVariance);
  EXPECT_LE(vq.sigma2(), kMinVariance + 8.0f * 1.2e-7f * glm::dot(Q, Q));
}

TEST(VsglMath, TwoTexelsGiveMidpointAndTok15Variance) {
  const glm::vec3 N(0.0f, 0.0f, 1.0f), src(0.0f, 0.0f, 5.0f), kd(0.25f);
  const glm::vec3 A(-1.0f, 0.0f, 0.0f), B(1.0f, 0.0f, 0.0f);
  TexelMoments m = texel_moments(true, A, N, kd, glm::vec3(0.0f), 1.0f, 1.0f, src, false);
  m += texel_moments(true, B, N, kd, glm::vec3(0.0f), 1.0f, 1.0f, src, false);
  const VsglRecord v = vsgl_from_moments(m, 1.0f, -1.0f, glm::vec2(0.0f), 0.0f, 2.0f);
  EXPECT_EQ(v.mu(), glm::vec3(0.0f));
  // Tok15 §3.2: sigma^2 = E|P|^2 - |mu|^2 = 1 for points at +-1, r^2 = 2 sigma^2.
  EXPECT_FLOAT_EQ(v.sigma2(), 1.0f);
  EXPECT_EQ(v.power(), glm::vec3(0.5f));
  EXPECT_EQ(v.center_pdf.w, 2.0f);
  EXPECT_EQ(v.level(), -1.0f);
}

TEST(VsglMath, PointsUniformOnADiskGiveItsRadius) {
  // Tok15 §3.2: "assuming a uniform distribution on a disk, r^2 = 2 sigma^2". Points spread
  // uniformly over a disk of radius R (a golden-angle spiral, equal areas per point), tilted and
  // away from the origin: r = sqrt(2 sigma^2) within 1 % of R.
  const glm::vec3 unit_centre(1.5f, 0.5f, -1.0f);  // scaled with R: float sums keep their precision
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
  const glm::vec3 e1 = glm::normalize(glm::cross(n, glm::vec3(1.0f, 0.0f, 0.0f)));
  const glm::vec3 e2 = glm::cross(n, e1);
  for (float R : {0.05f, 0.5f, 2.0f}) {
    const glm::vec3 centre = R * unit_centre;
    TexelMoments sum;
    const int count = 4096;
    for (int k = 0; k < count; ++k) {
      const float radius = R * std::sqrt((static_cast<float>(k) + 0.5f) / static_cast<float>(count));
      const float angle = 2.39996323f * static_cast<float>(k);
      const glm::vec3 P = centre + radius * (std::cos(angle) * e1 + std::sin(angle) * e2);
      sum += texel_moments(true, P, n, glm::vec3(0.1f), glm::vec3(0.0f), 1.0f, 1.0f, centre + n, false);
    }
    const VsglRecord v = vsgl_from_moments(sum, 1.0f, -1.0f, glm::vec2(0.0f), 0.0f, 0.0f);
    EXPECT_NEAR(std::sqrt(2.0f * v.sigma2()), R, 0.01f * R) << "R " << R;
    EXPECT_NEAR(glm::length(v.mu() - centre), 0.0f, 1e-3f * R + 1e-5f);
    EXPECT_NEAR(glm::dot(v.normal(), n), 1.0f, 1e-5f);
  }
}

TEST(VsglMath, OpposedNormalsCancelAndEmptyMomentsGiveNoLight) {
  const glm::vec3 src(0.0f, 0.0f, 0.0f), kd(0.5f);
  TexelMoments m = texel_moments(true, {0, -1, 0}, {0, 1, 0}, kd, glm::vec3(0.0f), 1.0f, 1.0f, src, false);
  m += texel_moments(true, {0, 1, 0}, {0, -1, 0}, kd, glm::vec3(0.0f), 1.0f, 1.0f, src, false);
  const VsglRecord v = vsgl_from_moments(m, 1.0f, 0.0f, glm::vec2(0.0f), 0.0f, 0.0f);
  EXPECT_EQ(v.normal_length.w, 0.0f);  // the filtered normal has no direction
  EXPECT_NEAR(glm::length(v.normal()), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(v.axis()), 1.0f, 1e-6f);

  TexelMoments empty;
  empty.m1 = glm::vec4(1.0f);
  empty.m2 = glm::vec4(1.0f);
  const VsglRecord none = vsgl_from_moments(empty, 7.0f, 3.0f, glm::vec2(0.5f), 2.0f, 0.0f);
  EXPECT_EQ(none.power(), glm::vec3(0.0f));
  EXPECT_EQ(none.specular(), glm::vec3(0.0f));
  EXPECT_EQ(none.mu(), glm::vec3(0.0f));
  EXPECT_EQ(none.sigma2(), kMinVariance);
  EXPECT_EQ(none.axis(), glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_EQ(none.sharpness(), 0.0f);
  EXPECT_EQ(none.level(), 3.0f);
  EXPECT_EQ(none.center_pdf, glm::vec4(0.5f, 0.5f, 2.0f, 0.0f));
}

// ---- SG evaluation --------------------------------------------------------------------------

TEST(SgEval, IntegralAndTripleProductMatchQuadrature) {
  for (float s : {0.0f, 0.004f, 0.0101f, 1.0f, 7.5f}) {
    const double q = sphere_integral([&](glm::dvec3 w) { return sg_d(w, {0, 0, 1}, s); }, {0, 0, 1});
    EXPECT_NEAR(sg_integral(s), q, 1e-5 * q) << "s " << s;
  }
  // Both branches against the closed form in double, up to the sharpest lobes.
  for (double s = 1e-6; s < 1e8; s *= 1.5) {
    const auto sf = static_cast<float>(s);
    const double closed = 2.0 * kPiD * -std::expm1(-2.0 * static_cast<double>(sf)) / static_cast<double>(sf);
    EXPECT_NEAR(sg_integral(sf), closed, 2e-6 * closed) << "s " << s;
    EXPECT_NEAR(sg_normalization(sf) * sg_integral(sf), 1.0f, 1e-6f);
  }
  struct Case {
    glm::vec3 a1; float s1; glm::vec3 a2; float s2; glm::vec3 a3; float s3;
  };
  const Case cases[] = {
      {{0, 0, 1}, 2.0f, {0, 1, 0}, 3.0f, {1, 0, 0}, 0.5f},
      {glm::normalize(glm::vec3(1, 1, 1)), 10.0f, {0, 0, 1}, 2.133f, glm::normalize(glm::vec3(1, 0, 1)), 25.0f},
      {{0, 0, -1}, 0.0f, {0, 0, 1}, 5.0f, {0, 0, 1}, 5.0f},
      {{0, 0, -1}, 4.0f, {0, 0, 1}, 4.0f, {1, 0, 0}, 0.0f},  // opposed equal lobes: sm = 0
  };
  for (const Case& c : cases) {
    const double q = sphere_integral(
        [&](glm::dvec3 w) {
          return sg_d(w, to_d(c.a1), c.s1) * sg_d(w, to_d(c.a2), c.s2) * sg_d(w, to_d(c.a3), c.s3);
        },
        to_d(c.s3 >= c.s1 ? c.a3 : c.a1));
    EXPECT_NEAR(sg_triple_integral(c.a1, c.s1, c.a2, c.s2, c.a3, c.s3), q, 1e-4 * q);
  }
}

TEST(SgEval, TripleProductStaysAccurateForVerySharpVisibility) {
  // lambda_v ~ 1e10 (a small VSGL far away): exp(sm - S) is formed without cancellation; compare
  // with the plain closed form in double on exactly unit axes (a float axis is unit only to
  // ~1e-7, which the plain form would amplify by s: that is why the float code does not use it).
  const glm::vec3 a1 = glm::normalize(glm::vec3(0.2f, 0.1f, -1.0f));
  const glm::vec3 a2(0.0f, 0.0f, 1.0f);
  const glm::vec3 a3 = glm::normalize(glm::vec3(0.01f, 0.0f, 1.0f));
  for (float s3 : {1e4f, 1e7f, 1e10f}) {
    const glm::dvec3 sum = 3.0 * glm::normalize(to_d(a1)) + 2.133 * glm::normalize(to_d(a2)) +
                           static_cast<double>(s3) * glm::normalize(to_d(a3));
    const double sm = glm::length(sum);
    const double S = 3.0 + 2.133 + static_cast<double>(s3);
    const double exact = std::exp(sm - S) * 2.0 * kPiD * (1.0 - std::exp(-2.0 * sm)) / sm;
    EXPECT_NEAR(sg_triple_integral(a1, 3.0f, a2, 2.133f, a3, s3), exact, 1e-4 * exact) << "s3 " << s3;
  }
}

// A single-texel VSGL: the moments of one texel at P (normal N, flux kd + ks, lit from src) with
// Tok15's sigma^2 given.
VsglRecord texel_vsgl(glm::vec3 P, glm::vec3 N, glm::vec3 kd, glm::vec3 ks, float roughness, glm::vec3 src,
                      float sigma2) {
  VsglRecord v = vsgl_from_moments(texel_moments(true, P, N, kd, ks, roughness, 1.0f, src, false), 1.0f, 0.0f,
                                   glm::vec2(0.0f), 1.0f, 1.0f);
  v.position_variance.w = sigma2;
  return v;
}

// Tok15 Eq. 1 in double, with the suite's two-lobe BRDFs (DESIGN.md §8): the VPL at mu of flux
// Phi_d + Phi_s, its emission Phi_d / pi + Phi_s c(lambda) G(w; -axis, lambda), the receiver's
// rho_d / pi + rho_s c(s_r) G(w; axis_r, s_r), the exact cosines, over d^2.
glm::dvec3 eq1_radiance(const VsglRecord& v, glm::vec3 x, glm::vec3 n, glm::vec3 wo, glm::vec3 rho_d, glm::vec3 rho_s,
                        float roughness) {
  const glm::dvec3 to = to_d(v.mu() - x);
  const double d = glm::length(to);
  const glm::dvec3 w = to / d;
  const auto c = [](double s) { return s > 0.0 ? s / (2.0 * kPiD * -std::expm1(-2.0 * s)) : 1.0 / (4.0 * kPiD); };
  const double lambda = v.sharpness();
  const glm::dvec3 emission =
      (to_d(v.power()) - to_d(v.specular())) / kPiD + to_d(v.specular()) * c(lambda) * sg_d(w, -to_d(v.axis()), lambda);
  const glm::dvec3 nd = to_d(n), wod = to_d(wo);
  const double alpha = std::max(static_cast<double>(roughness), 1e-3);
  const double s_r = (2.0 / (alpha * alpha)) / (4.0 * std::max(glm::dot(nd, wod), 1e-4));
  const glm::dvec3 axis_r = -wod + 2.0 * glm::dot(nd, wod) * nd;
  const glm::dvec3 brdf = to_d(rho_d) / kPiD + to_d(rho_s) * c(s_r) * sg_d(w, axis_r, s_r);
  const double cosines = std::max(glm::dot(w, nd), 0.0) * std::max(glm::dot(-w, to_d(v.normal())), 0.0);
  return emission * brdf * cosines / (d * d);
}

TEST(SgEval, SingleTexelVsglAtDistance100RadiiIsTheVplOfEq1) {
  // Tok15 §3.3: as r -> 0 the VSGL tends to Eq. 1. At d / r = 100, within 1e-3 relative, for matte
  // and glossy lights and receivers (the glossy ones sharp enough to take the integral branch at
  // larger r).
  const glm::vec3 N(0.0f, 1.0f, 0.0f);
  const glm::vec3 P(0.0f, 0.0f, 0.0f);
  const glm::vec3 src = P + glm::vec3(-2.0f, 3.0f, 0.5f);
  const glm::vec3 x(1.5f, 1.2f, -0.4f);
  const glm::vec3 n = glm::normalize(glm::vec3(-0.4f, -1.0f, 0.3f));
  const float d = glm::length(x - P);
  const float r = d / 100.0f;
  int checked = 0;
  for (float light_roughness : {1.0f, 0.3f, 0.05f})
    for (glm::vec3 ks : {glm::vec3(0.0f), glm::vec3(0.3f, 0.2f, 0.1f)})
      for (float roughness : {1.0f, 0.2f}) {
        const VsglRecord v = texel_vsgl(P, N, {0.4f, 0.5f, 0.6f}, ks, light_roughness, src, 0.5f * r * r);
        const glm::vec3 wo = glm::normalize(glm::vec3(0.2f, -1.0f, 0.5f));
        const glm::vec3 L = vsgl_radiance_surface(v, x, n, wo, {0.5f, 0.4f, 0.3f}, {0.2f, 0.3f, 0.4f}, roughness);
        const glm::dvec3 ref = eq1_radiance(v, x, n, wo, {0.5f, 0.4f, 0.3f}, {0.2f, 0.3f, 0.4f}, roughness);
        for (int c = 0; c < 3; ++c) {
          ASSERT_GT(ref[c], 0.0);
          EXPECT_NEAR(L[c], ref[c], 1e-3 * ref[c])
              << "light alpha " << light_roughness << " ks " << ks.r << " receiver alpha " << roughness;
        }
        ++checked;
      }
  EXPECT_EQ(checked, 12);
}

TEST(SgEval, AVplOnTheReceiversPlaneOrBehindItAddsExactlyZero) {
  // Tok15 Eq. 3's exact cosines: a lit floor does not light itself (the clamped-cosine SG of old
  // left 0.139 of its peak at 90 degrees: a 1/d^2 tail that grew with every finer RSM).
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const glm::vec3 src(0.0f, 5.0f, 0.0f);
  for (float sigma2 : {kMinVariance, 1e-4f, 0.01f, 1.0f})
    for (glm::vec3 ks : {glm::vec3(0.0f), glm::vec3(0.5f)}) {
      const VsglRecord vpl = texel_vsgl({0.0f, 0.0f, 0.0f}, up, glm::vec3(0.5f), ks, 0.3f, src, sigma2);
      for (float dx : {1e-3f, 0.1f, 1.0f, 10.0f}) {
        const glm::vec3 on_plane(dx, 0.0f, 0.5f * dx);
        const glm::vec3 wo = glm::normalize(glm::vec3(-1.0f, 1.0f, 0.0f));
        EXPECT_EQ(vsgl_radiance_surface(vpl, on_plane, up, wo, glm::vec3(1.0f), glm::vec3(0.5f), 0.2f), glm::vec3(0.0f))
            << "on the plane, sigma2 " << sigma2 << " dx " << dx;
        // A receiver above the VPL facing away from it (its normal up) gets nothing.
        const glm::vec3 above(dx, 1.0f, 0.0f);
        EXPECT_EQ(vsgl_radiance_surface(vpl, above, up, up, glm::vec3(1.0f), glm::vec3(0.5f), 0.2f), glm::vec3(0.0f));
        // A receiver below the VPL's surface (behind it) gets nothing either.
        const glm::vec3 below(dx, -1.0f, 0.0f);
        EXPECT_EQ(vsgl_radiance_surface(vpl, below, up, up, glm::vec3(1.0f), glm::vec3(0.5f), 0.2f), glm::vec3(0.0f));
      }
    }
  // Facing each other, it is positive.
  const VsglRecord vpl = texel_vsgl({0.0f, 0.0f, 0.0f}, up, glm::vec3(0.5f), glm::vec3(0.0f), 0.3f, src, 1e-4f);
  EXPECT_GT(vsgl_radiance_surface(vpl, {0.2f, 1.0f, 0.0f}, -up, -up, glm::vec3(1.0f), glm::vec3(0.0f), 1.0f).x, 0.0f);
}

TEST(SgEval, BiasReductionSwitchesToThePulledOutFormWhereRhoIsSmooth) {
  // A matte light and receiver: rho has no lobe (sharpness 0), so it is always pulled out
  // (Tok15 §3.3) and the VSGL is rho(w_i) Omega / (pi r^2) exactly, even at d = 0.
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const VsglRecord v = texel_vsgl({0.0f, 0.0f, 0.0f}, up, glm::vec3(0.5f), glm::vec3(0.0f), 1.0f, {0, 5, 0}, 0.02f);
  const glm::vec3 x(0.1f, 0.3f, 0.0f);
  const glm::vec3 n = glm::normalize(glm::vec3(-0.1f, -1.0f, 0.0f));
  const glm::vec3 L = vsgl_radiance_surface(v, x, n, n, glm::vec3(1.0f), glm::vec3(0.0f), 1.0f);
  const double d = glm::length(to_d(x));
  const double r2 = 2.0 * 0.02;
  const double solid = 2.0 * kPiD * (1.0 - d / std::sqrt(d * d + r2));
  const glm::dvec3 w = -to_d(x) / d;
  const double rho = (0.5 / kPiD) * (1.0 / kPiD) * std::max(glm::dot(w, to_d(n)), 0.0) * std::max(-w.y, 0.0);
  EXPECT_NEAR(L.x, rho * solid / (kPiD * r2), 1e-5 * rho * solid / (kPiD * r2));
  // A sharp receiver lobe aimed at a wide VSGL takes the integral branch: finite and positive.
  VsglRecord wide = v;
  wide.position_variance.w = 0.5f;
  const glm::vec3 wo = glm::reflect(glm::normalize(x), n);
  const glm::vec3 sharp = vsgl_radiance_surface(wide, x, n, wo, glm::vec3(0.0f), glm::vec3(1.0f), 0.05f);
  EXPECT_TRUE(std::isfinite(sharp.x));
  EXPECT_GT(sharp.x, 0.0f);
}

TEST(SgEval, ImportanceIsTheShadingOfTheTexelByTheCameraVsgl) {
  // The BRSM importance is made as shading is (DESIGN.md §8): the texel's flux stands for its
  // albedos, and the direction to the light for the viewer's.
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const VsglRecord cam = texel_vsgl({0.0f, 2.0f, 0.0f}, -up, glm::vec3(0.3f, 0.5f, 0.2f), glm::vec3(0.1f), 0.4f,
                                    {1.0f, 0.0f, 0.0f}, 0.01f);
  const glm::vec3 P(0.3f, 0.0f, 0.1f), to_light = glm::normalize(glm::vec3(-1.0f, 2.0f, 0.0f));
  const glm::vec3 fd(0.2f, 0.1f, 0.05f), fs(0.05f);
  const glm::vec3 e = vsgl_radiance_surface(cam, P, up, to_light, fd, fs, 0.3f);
  EXPECT_GT(e.r + e.g + e.b, 0.0f);
  EXPECT_EQ(vsgl_importance_to_texel(cam, P, up, to_light, fd, fs, 0.3f), e.r + e.g + e.b);
  // A texel facing away from the camera VSGL receives none.
  EXPECT_EQ(vsgl_importance_to_texel(cam, P, -up, to_light, fd, fs, 0.3f), 0.0f);
}

TEST(SgEval, NoSingularityAtZeroDistance) {
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  for (float sigma2 : {0.0f, kMinVariance, 1e-4f, 1.0f}) {
    VsglRecord v = texel_vsgl({0, 0, 0}, {0, 0, -1}, glm::vec3(0.5f), glm::vec3(0.5f), 0.3f, {0, 0, -3}, sigma2);
    v.position_variance.w = sigma2;
    for (float dz : {0.0f, 1e-8f, 1e-6f, 1e-3f}) {
      const glm::vec3 L = vsgl_radiance_surface(v, {0, 0, -dz}, n, n, glm::vec3(0.5f), glm::vec3(0.5f), 0.2f);
      const float I = vsgl_importance_to_texel(v, {0, 0, -dz}, n, n, glm::vec3(0.5f), glm::vec3(0.5f), 0.2f);
      for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(std::isfinite(L[c])) << sigma2 << " " << dz;
        EXPECT_GE(L[c], 0.0f);
      }
      EXPECT_TRUE(std::isfinite(I));
      EXPECT_GE(I, 0.0f);
    }
  }
}

}  // namespace
}  // namespace vsgl
