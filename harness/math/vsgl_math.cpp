// Twins of kernels/include/vsgl_math.glsl and sg_eval.glsl: keep every formula, branch and
// constant identical to the GLSL (comments with the reasons live there).
#include "harness/math/vsgl_math.hpp"

#include "kernels/include/interface/shading.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vsgl {

std::string shading_model_text() {
  char alpha[32];
  std::snprintf(alpha, sizeof alpha, "%g", double{gpu::kBiasReductionAlpha});
  return "Tok15 Eq. 3 (K = 2 lobes, exact cosines), §3.3 bias reduction at alpha = " + std::string(alpha);
}

// ---- vsgl_math.glsl ------------------------------------------------------------------------

float mean_resultant_length(float lambda) {
  if (lambda < 1e-3f) return lambda / 3.0f;
  if (lambda < 0.5f) {
    const float l2 = lambda * lambda;
    return lambda * (1.0f / 3.0f - l2 * (1.0f / 45.0f - l2 * (2.0f / 945.0f - l2 * (1.0f / 4725.0f))));
  }
  if (lambda > 20.0f) return 1.0f - 1.0f / lambda;
  const float e = std::exp(-2.0f * lambda);
  return (1.0f + e) / (1.0f - e) - 1.0f / lambda;
}

float banerjee_sharpness(float r) {
  const float rc = std::clamp(r, 0.0f, kMaxMeanLength);
  const float r2 = rc * rc;
  return std::clamp(rc * (3.0f - r2) / (1.0f - r2), 0.0f, kMaxSharpness);
}

float reflection_lobe_sharpness(float roughness, float cos_n) {
  const float alpha = std::max(roughness, kMinRoughness);
  return std::clamp((2.0f / (alpha * alpha)) / (4.0f * std::max(cos_n, kMinCosine)), 0.0f, kMaxSharpness);
}

glm::vec3 texel_specular_direction(glm::vec3 P, glm::vec3 N, float roughness, glm::vec3 source_pos) {
  const glm::vec3 to_source = source_pos - P;
  const float dist2 = glm::dot(to_source, to_source);
  const glm::vec3 omega_in = dist2 > 0.0f ? to_source * (1.0f / std::sqrt(dist2)) : N;
  return mean_resultant_length(reflection_lobe_sharpness(roughness, glm::dot(N, omega_in))) *
         glm::reflect(-omega_in, N);
}

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

TexelMoments texel_moments(bool valid, glm::vec3 P, glm::vec3 N, glm::vec3 diffuse, glm::vec3 specular,
                           float roughness, float pdf, glm::vec3 source_pos, bool camera_view) {
  TexelMoments m;
  if (!valid) return m;
  const glm::vec3 phi = diffuse + specular;
  const float w = camera_view ? luminance(phi) : phi.r + phi.g + phi.b;
  const float s = specular.r + specular.g + specular.b;
  m.m0 = glm::vec4(phi, w);
  m.m1 = glm::vec4(w * P, w * glm::dot(P, P));
  m.m2 = glm::vec4(w * N, pdf);
  m.m3 = glm::vec4(specular, 0.0f);
  m.m4 = glm::vec4(s > 0.0f ? s * texel_specular_direction(P, N, roughness, source_pos) : glm::vec3(0.0f), 0.0f);
  return m;
}

VsglRecord vsgl_from_moments(const TexelMoments& m, float power_scale, float level, glm::vec2 center, float density,
                             float texel_count) {
  VsglRecord v;
  v.center_pdf = glm::vec4(center, density, texel_count);
  const float W = m.m0.w;
  if (!(W > 0.0f)) {
    v.position_variance = glm::vec4(0.0f, 0.0f, 0.0f, kMinVariance);
    v.power_sharpness = glm::vec4(0.0f);
    v.axis_level = glm::vec4(0.0f, 0.0f, 1.0f, level);
    v.normal_length = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);
    v.specular_power = glm::vec4(0.0f);
    return v;
  }
  const glm::vec3 mu = glm::vec3(m.m1) / W;
  const float sigma2 = std::max(m.m1.w / W - glm::dot(mu, mu), kMinVariance);
  const glm::vec3 mean_normal = glm::vec3(m.m2) / W;
  const float normal_len = glm::length(mean_normal);
  const glm::vec3 normal = normal_len > 0.0f ? mean_normal / normal_len : glm::vec3(0.0f, 0.0f, 1.0f);
  const float s = m.m3.r + m.m3.g + m.m3.b;
  const glm::vec3 mean_dir = s > 0.0f ? glm::vec3(m.m4) / s : glm::vec3(0.0f);
  const float len = glm::length(mean_dir);
  const glm::vec3 axis = len > 0.0f ? mean_dir / len : normal;
  const float lambda = banerjee_sharpness(std::min(len, kMaxMeanLength));
  v.position_variance = glm::vec4(mu, sigma2);
  v.power_sharpness = glm::vec4(power_scale * glm::vec3(m.m0), lambda);
  v.axis_level = glm::vec4(axis, level);
  v.normal_length = glm::vec4(normal, normal_len);
  v.specular_power = glm::vec4(power_scale * glm::vec3(m.m3), 0.0f);
  return v;
}

// ---- sg_eval.glsl --------------------------------------------------------------------------

float sg_integral(float s) {
  if (s < 0.01f) return 4.0f * kPi * (1.0f - s * (1.0f - s * (2.0f / 3.0f - s * (1.0f / 3.0f))));
  return 2.0f * kPi * (1.0f - std::exp(-2.0f * s)) / s;
}

float sg_normalization(float s) { return 1.0f / sg_integral(s); }

float sg_triple_integral(glm::vec3 a1, float s1, glm::vec3 a2, float s2, glm::vec3 a3, float s3) {
  const float sm = glm::length(s1 * a1 + s2 * a2 + s3 * a3);
  const float total = s1 + s2 + s3;
  const glm::vec3 d12 = a1 - a2;
  const glm::vec3 d13 = a1 - a3;
  const glm::vec3 d23 = a2 - a3;
  const float spread = s1 * s2 * glm::dot(d12, d12) + s1 * s3 * glm::dot(d13, d13) + s2 * s3 * glm::dot(d23, d23);
  const float log_amplitude = total > 0.0f ? -spread / (sm + total) : 0.0f;
  return std::exp(log_amplitude) * sg_integral(sm);
}

VsglView vsgl_view_from(const VsglRecord& v, glm::vec3 x, glm::vec3 fallback_dir) {
  VsglView view;
  const glm::vec3 to_mean = v.mu() - x;
  float d = glm::length(to_mean);
  if (d < kMinDistance) {
    d = kMinDistance;
    view.wc = fallback_dir;
  } else {
    view.wc = to_mean / d;
  }
  const float r2 = 2.0f * std::max(v.sigma2(), kMinVariance);
  const float hyp = std::sqrt(d * d + r2);
  const float one_minus_cos = r2 / (hyp * (hyp + d));
  view.solid_angle = 2.0f * kPi * one_minus_cos;
  view.lambda_v = 2.0f / one_minus_cos;
  view.inv_area = 1.0f / (kPi * r2);
  return view;
}

glm::vec3 vsgl_two_lobe_radiance(const VsglRecord& v, glm::vec3 x, glm::vec3 n, const TwoLobes& f) {
  const VsglView view = vsgl_view_from(v, x, n);
  const float cosines = std::max(glm::dot(view.wc, n), 0.0f) * std::max(glm::dot(-view.wc, v.normal()), 0.0f);
  if (!(cosines > 0.0f)) return glm::vec3(0.0f);
  const glm::vec3 phi_s = v.specular();
  const float lambda = v.sharpness();
  const glm::vec3 emit_axis = -v.axis();
  const glm::vec3 light_d = glm::max(v.power() - phi_s, glm::vec3(0.0f)) / kPi;
  const glm::vec3 light_s = phi_s * sg_normalization(lambda);
  const bool receiver_glossy = f.specular.r + f.specular.g + f.specular.b > 0.0f;
  const bool light_glossy = phi_s.r + phi_s.g + phi_s.b > 0.0f;
  float eta = 0.0f;
  if (receiver_glossy) eta = std::max(eta, f.sharpness);
  if (light_glossy) eta = std::max(eta, lambda);
  if (receiver_glossy && light_glossy) eta = std::max(eta, glm::length(f.sharpness * f.axis + lambda * emit_axis));
  glm::vec3 sum;
  if (eta < gpu::kBiasReductionAlpha * view.lambda_v) {
    const float g_s = std::exp(f.sharpness * (glm::dot(view.wc, f.axis) - 1.0f));
    const float g_i = std::exp(lambda * (glm::dot(view.wc, emit_axis) - 1.0f));
    sum = (f.diffuse + f.specular * g_s) * (light_d + light_s * g_i) * view.solid_angle;
  } else {
    const glm::vec3 a = view.wc;
    sum = 2.0f * (f.diffuse * light_d * sg_integral(view.lambda_v) +
                  f.diffuse * light_s * sg_triple_integral(emit_axis, lambda, a, view.lambda_v, a, 0.0f) +
                  f.specular * light_d * sg_triple_integral(f.axis, f.sharpness, a, view.lambda_v, a, 0.0f) +
                  f.specular * light_s * sg_triple_integral(f.axis, f.sharpness, emit_axis, lambda, a, view.lambda_v));
  }
  return sum * (cosines * view.inv_area);
}

TwoLobes surface_lobes(glm::vec3 n, glm::vec3 wo, glm::vec3 rho_d, glm::vec3 rho_s, float roughness) {
  TwoLobes f;
  f.sharpness = reflection_lobe_sharpness(roughness, glm::dot(n, wo));
  f.axis = glm::reflect(-wo, n);
  f.diffuse = rho_d / kPi;
  f.specular = rho_s * sg_normalization(f.sharpness);
  return f;
}

glm::vec3 vsgl_radiance_surface(const VsglRecord& v, glm::vec3 x, glm::vec3 n, glm::vec3 wo, glm::vec3 rho_d,
                                glm::vec3 rho_s, float roughness) {
  return vsgl_two_lobe_radiance(v, x, n, surface_lobes(n, wo, rho_d, rho_s, roughness));
}

float vsgl_importance_to_texel(const VsglRecord& cam, glm::vec3 P, glm::vec3 N, glm::vec3 to_light,
                               glm::vec3 flux_diffuse, glm::vec3 flux_specular, float roughness) {
  const glm::vec3 e = vsgl_radiance_surface(cam, P, N, to_light, flux_diffuse, flux_specular, roughness);
  return e.r + e.g + e.b;
}

}  // namespace vsgl
