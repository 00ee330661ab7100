#ifndef SG_EVAL_GLSL
#define SG_EVAL_GLSL
// Evaluating a VSGL at a receiver without visibility (DESIGN.md §8, Tok15 §3.1), in closed form with
// spherical Gaussians G(w; a, s) = exp(s (dot(w, a) - 1)).
//
//   L = 1 / (pi r^2) * integral over S^2 of I(w) f(w) V(w) dw            (Tok15 Eq. 2)
//   I(w) = Phi c(lambda) G(w; -xi, lambda)   radiant intensity of the VSGL toward -w,
//          c(s) = 1 / integral of G(.; s) = s / (2 pi (1 - exp(-2 s)))  (1 / (4 pi) at s = 0)
//   V(w) = 2 G(w; wc, lambda_v), lambda_v = 4 pi / solid, solid = 2 pi (1 - cos theta),
//          cos theta = d / sqrt(d^2 + r^2)                              (no singularity at d = 0)
//   f(w) = the receiver's response as a sum of SGs.
// A product of SGs is an SG, so each term is a triple-product integral of SGs. As r -> 0 and d
// grows, L tends to the point-light value I(wc) f(wc) / d^2.
// C++ twin: harness/math/vsgl_math.hpp.
#include "vsgl_math.glsl"

// The clamped cosine max(dot(w, n), 0) as one SG: 1.17 G(w; n, 2.133).
const float VSGL_COSINE_SG_AMPLITUDE = 1.17;
const float VSGL_COSINE_SG_SHARPNESS = 2.133;
// A receiver closer than this to the VSGL's mean uses this distance and its own normal as wc.
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

// The VSGL as seen from x: direction wc to its mean, visibility-SG sharpness lambda_v and the
// factor 2 / (pi r^2) (the 2 of V(w) = 2 G, and Tok15's 1 / (pi r^2)).
struct VsglView {
  vec3 wc;
  float lambda_v;
  float scale;
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
  view.lambda_v = 2.0 / one_minus_cos;             // 4 pi / (2 pi (1 - cos theta))
  view.scale = 2.0 / (VSGL_PI * r2);
  return view;
}

// (a) Shading: outgoing radiance toward wo (unit, toward the viewer) at a surface point x with
// normal n, diffuse albedo rho_d, specular albedo rho_s and GGX roughness. The receiver's BRDF
// times cosine is f(w) = rho_d / pi * 1.17 G(w; n, 2.133) + amp G(w; axis_r, s_r) max(dot(axis_r, n), 0)
// with axis_r = reflect(-wo, n), s_r = (2 / alpha^2) / (4 max(dot(n, wo), 1e-4)) and
// amp = rho_s / sg_integral(s_r) (the lobe's albedo is rho_s; its cosine is taken at axis_r).
vec3 vsgl_radiance_surface(Vsgl v, vec3 x, vec3 n, vec3 wo, vec3 rho_d, vec3 rho_s, float roughness) {
  VsglView view = vsgl_view_from(v, x, n);
  vec3 phi = v.power_sharpness.rgb;
  float lambda = v.power_sharpness.w;
  vec3 emit_axis = -v.axis_level.xyz;  // I(w) peaks where -w is the VSGL's axis
  float emission = sg_normalization(lambda) * view.scale;

  float diffuse_term = VSGL_COSINE_SG_AMPLITUDE / VSGL_PI *
      sg_triple_integral(emit_axis, lambda, n, VSGL_COSINE_SG_SHARPNESS, view.wc, view.lambda_v);

  float alpha = max(roughness, VSGL_MIN_ROUGHNESS);
  float s_r = (2.0 / (alpha * alpha)) / (4.0 * max(dot(n, wo), VSGL_MIN_COSINE));
  vec3 axis_r = reflect(-wo, n);
  float specular_term = max(dot(axis_r, n), 0.0) / sg_integral(s_r) *
      sg_triple_integral(emit_axis, lambda, axis_r, s_r, view.wc, view.lambda_v);

  return phi * (emission * (rho_d * diffuse_term + rho_s * specular_term));
}

// (b) BRSM importance (DESIGN.md §8): how much of the camera VSGL `cam` (its power = reflectance, the
// importance emitted toward the camera's surfaces) a VPL at x receives through its own normalized
// emission lobe c(vpl_lambda) G(w; vpl_axis, vpl_lambda). Importance is a scalar: the rgb power
// of the camera VSGL enters as its channel sum (Phi.r + Phi.g + Phi.b), no luminance weighting.
// A VPL on the VSGL's mean (d < 1e-6) uses vpl_axis as wc.
float vsgl_importance_to_vpl(Vsgl cam, vec3 x, vec3 vpl_axis, float vpl_lambda) {
  VsglView view = vsgl_view_from(cam, x, vpl_axis);
  vec3 phi = cam.power_sharpness.rgb;
  float lambda = cam.power_sharpness.w;
  float emission = (phi.r + phi.g + phi.b) * sg_normalization(lambda) * view.scale;
  return emission * sg_normalization(vpl_lambda) *
      sg_triple_integral(-cam.axis_level.xyz, lambda, vpl_axis, vpl_lambda, view.wc, view.lambda_v);
}

#endif  // SG_EVAL_GLSL
