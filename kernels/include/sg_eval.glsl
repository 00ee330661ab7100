#ifndef SG_EVAL_GLSL
#define SG_EVAL_GLSL
// Evaluating a VSGL at a receiver without visibility: Tok15 Eq. 2 and Eq. 3 with K = 2 lobes on
// each side and §3.3's consistent bias reduction (DESIGN.md §8), with spherical Gaussians
// G(w; a, s) = exp(s (dot(w, a) - 1)).
//
//   L = 1 / (pi r^2) * integral over S^2 of rho(w) V(w) dw                     (Tok15 Eq. 2)
//   rho(w) = f_s(w) f_i(w) <w_i, n_s> <-w_i, n_i>: the receiver's BRDF f_s, the light's emission f_i
//          (its power times its BRDF) and the exact clamped cosines at the direction w_i to the
//          light's mean, pulled out of the integral (Tok15 Eq. 3: smooth, and exactly 0 when the
//          receiver faces away or the light lies in the receiver's plane);
//   f_s(w) = rho_d / pi + rho_s c(s_r) G(w; axis_r, s_r),   f_i(w) = Phi_d / pi + Phi_s c(lambda) G(w; -axis, lambda):
//          a diffuse lobe of zero sharpness and a normalized specular SG, c(s) = 1 / integral of G;
//   V(w) = 2 G(w; w_i, lambda_v), lambda_v = 4 pi / Omega, Omega = 2 pi (1 - cos theta),
//          cos theta = d / sqrt(d^2 + r^2)                                    (no singularity at d = 0).
// Each of the four lobe pairs is then a closed-form product integral of SGs. §3.3: where rho's
// sharpest lobe is smoother than alpha lambda_v, rho is pulled out instead: L = rho(w_i) Omega / (pi r^2),
// which tends to the VPL of Eq. 1, rho(w_i) / d^2, as r -> 0.
// C++ twin: harness/math/vsgl_math.hpp.
#include "vsgl_math.glsl"
#include "interface/shading.h"

// A receiver closer than this to the VSGL's mean uses this distance and its own normal as w_i.
const float VSGL_MIN_DISTANCE = 1e-6;

// Integral over S^2 of G(w; a, s) = 2 pi (1 - exp(-2 s)) / s; a series below s = 0.01, where the
// subtraction would cancel in float (4 pi (1 - s + 2/3 s^2 - 1/3 s^3), error < 3e-9 relative).
float sg_integral(float s) {
  if (s < 0.01) return 4.0 * VSGL_PI * (1.0 - s * (1.0 - s * (2.0 / 3.0 - s * (1.0 / 3.0))));
  return 2.0 * VSGL_PI * (1.0 - exp(-2.0 * s)) / s;
}

// c(s): the amplitude that normalizes G(.; s) to unit integral.
float sg_normalization(float s) { return 1.0 / sg_integral(s); }

// Integral over S^2 of G(w; a1, s1) G(w; a2, s2) G(w; a3, s3) (unit axes):
//   = exp(sm - S) * sg_integral(sm), S = s1 + s2 + s3, sm = |s1 a1 + s2 a2 + s3 a3|.
// sm - S is formed without cancellation (lambda_v reaches 1e10 and more for small VSGLs):
//   sm^2 - S^2 = -sum_{i<j} s_i s_j |a_i - a_j|^2,  so  sm - S = -(that sum) / (sm + S).
float sg_triple_integral(vec3 a1, float s1, vec3 a2, float s2, vec3 a3, float s3) {
  float sm = length(s1 * a1 + s2 * a2 + s3 * a3);
  float total = s1 + s2 + s3;
  vec3 d12 = a1 - a2;
  vec3 d13 = a1 - a3;
  vec3 d23 = a2 - a3;
  float spread = s1 * s2 * dot(d12, d12) + s1 * s3 * dot(d13, d13) + s2 * s3 * dot(d23, d23);
  float log_amplitude = total > 0.0 ? -spread / (sm + total) : 0.0;
  return exp(log_amplitude) * sg_integral(sm);
}

// The VSGL as seen from x: direction wc to its mean, the cone's solid angle Omega, the
// visibility-SG sharpness lambda_v = 4 pi / Omega and Tok15's 1 / (pi r^2).
struct VsglView {
  vec3 wc;
  float lambda_v;
  float solid_angle;
  float inv_area;
};

VsglView vsgl_view_from(Vsgl v, vec3 x, vec3 fallback_dir) {
  VsglView view;
  vec3 to_mean = v.position_variance.xyz - x;
  float d = length(to_mean);
  if (d < VSGL_MIN_DISTANCE) {
    d = VSGL_MIN_DISTANCE;
    view.wc = fallback_dir;
  } else {
    view.wc = to_mean / d;
  }
  float r2 = 2.0 * max(v.position_variance.w, VSGL_MIN_VARIANCE);
  float hyp = sqrt(d * d + r2);
  float one_minus_cos = r2 / (hyp * (hyp + d));  // 1 - d / hyp without cancellation
  view.solid_angle = 2.0 * VSGL_PI * one_minus_cos;
  view.lambda_v = 2.0 / one_minus_cos;  // 4 pi / (2 pi (1 - cos theta))
  view.inv_area = 1.0 / (VSGL_PI * r2);
  return view;
}

// A BRDF (or a light's emission) as Tok15's K = 2 lobes: a diffuse coefficient (an SG of zero
// sharpness) and a normalized specular SG with its coefficient, axis and sharpness.
struct TwoLobes {
  vec3 diffuse;   // coefficient of the zero-sharpness lobe
  vec3 specular;  // coefficient of G(w; axis, sharpness), normalization included
  vec3 axis;
  float sharpness;
};

// Radiance (or importance) toward wo leaving a receiver at x with normal n and response `f`, lit by
// the VSGL v (DESIGN.md §8): Tok15 Eq. 3 with §3.3's bias reduction.
vec3 vsgl_two_lobe_radiance(Vsgl v, vec3 x, vec3 n, TwoLobes f) {
  VsglView view = vsgl_view_from(v, x, n);
  float cosines = max(dot(view.wc, n), 0.0) * max(dot(-view.wc, v.normal_length.xyz), 0.0);
  if (!(cosines > 0.0)) return vec3(0.0);
  vec3 phi_s = v.specular_power.rgb;
  float lambda = v.power_sharpness.w;
  vec3 emit_axis = -v.axis_level.xyz;  // f_i(w) peaks where -w is the VSGL's axis
  vec3 light_d = max(v.power_sharpness.rgb - phi_s, vec3(0.0)) / VSGL_PI;
  vec3 light_s = phi_s * sg_normalization(lambda);
  bool receiver_glossy = f.specular.r + f.specular.g + f.specular.b > 0.0;
  bool light_glossy = phi_s.r + phi_s.g + phi_s.b > 0.0;
  // Tok15 §3.3: the sharpest lobe of rho (the products' sharpness |s1 a1 + s2 a2|), against alpha lambda_v.
  float eta = 0.0;
  if (receiver_glossy) eta = max(eta, f.sharpness);
  if (light_glossy) eta = max(eta, lambda);
  if (receiver_glossy && light_glossy) eta = max(eta, length(f.sharpness * f.axis + lambda * emit_axis));
  vec3 sum;
  if (eta < kBiasReductionAlpha * view.lambda_v) {
    float g_s = exp(f.sharpness * (dot(view.wc, f.axis) - 1.0));
    float g_i = exp(lambda * (dot(view.wc, emit_axis) - 1.0));
    sum = (f.diffuse + f.specular * g_s) * (light_d + light_s * g_i) * view.solid_angle;
  } else {
    vec3 a = view.wc;  // G_V's axis; a zero sharpness makes a lobe drop out of the product
    sum = 2.0 * (f.diffuse * light_d * sg_integral(view.lambda_v) +
                 f.diffuse * light_s * sg_triple_integral(emit_axis, lambda, a, view.lambda_v, a, 0.0) +
                 f.specular * light_d * sg_triple_integral(f.axis, f.sharpness, a, view.lambda_v, a, 0.0) +
                 f.specular * light_s * sg_triple_integral(f.axis, f.sharpness, emit_axis, lambda, a, view.lambda_v));
  }
  return sum * (cosines * view.inv_area);
}

// A surface's BRDF as two lobes: rho_d / pi, and rho_s times a normalized SG around reflect(-wo, n)
// of sharpness (2 / alpha^2) / (4 max(dot(n, wo), 1e-4)) (the NDF warped to the reflection lobe,
// Wang et al. 2009), so that its directional albedo is rho_s <axis_r, n>.
TwoLobes surface_lobes(vec3 n, vec3 wo, vec3 rho_d, vec3 rho_s, float roughness) {
  TwoLobes f;
  f.sharpness = reflection_lobe_sharpness(roughness, dot(n, wo));
  f.axis = reflect(-wo, n);
  f.diffuse = rho_d / VSGL_PI;
  f.specular = rho_s * sg_normalization(f.sharpness);
  return f;
}

// (a) Shading: outgoing radiance toward wo (unit, toward the viewer) at a surface point x with
// normal n, diffuse albedo rho_d, specular albedo rho_s and GGX roughness.
vec3 vsgl_radiance_surface(Vsgl v, vec3 x, vec3 n, vec3 wo, vec3 rho_d, vec3 rho_s, float roughness) {
  return vsgl_two_lobe_radiance(v, x, n, surface_lobes(n, wo, rho_d, rho_s, roughness));
}

// (b) BRSM importance (DESIGN.md §8), made the same way: the camera VSGL `cam` (its power = the
// reflectance of the camera's surfaces) lights an RSM texel at P with normal N whose "albedos" are
// its diffuse and specular flux, seen from the spot light (wo toward the light). Importance is a
// scalar: the channel sum of that radiance.
float vsgl_importance_to_texel(Vsgl cam, vec3 P, vec3 N, vec3 to_light, vec3 flux_diffuse, vec3 flux_specular,
                               float roughness) {
  vec3 e = vsgl_radiance_surface(cam, P, N, to_light, flux_diffuse, flux_specular, roughness);
  return e.r + e.g + e.b;
}

#endif  // SG_EVAL_GLSL
