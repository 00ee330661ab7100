// Twins of kernels/include/vsgl_math.glsl and sg_eval.glsl: keep every formula, branch and
// constant identical to the GLSL (comments with the reasons live there).
#include "harness/math/vsgl_math.hpp"

#include <algorithm>
#include <cmath>

namespace vsgl {

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

glm::vec3 texel_emission_lobe(glm::vec3 P, glm::vec3 N, glm::vec3 diffuse, glm::vec3 specular, float roughness,
                              glm::vec3 source_pos) {
  const float pd = diffuse.r + diffuse.g + diffuse.b;
  const float ps = specular.r + specular.g + specular.b;
  const float total = pd + ps;
  if (!(total > 0.0f)) return glm::vec3(0.0f);
  const glm::vec3 to_source = source_pos - P;
  const float dist2 = glm::dot(to_source, to_source);
  const glm::vec3 omega_in = dist2 > 0.0f ? to_source * (1.0f / std::sqrt(dist2)) : N;
  const float alpha = std::max(roughness, kMinRoughness);
  const float cos_in = glm::dot(N, omega_in);
  const float lambda_s =
      std::clamp((2.0f / (alpha * alpha)) / (4.0f * std::max(cos_in, kMinCosine)), 0.0f, kMaxSharpness);
  const glm::vec3 mirror = glm::reflect(-omega_in, N);
  return (pd * kDiffuseMeanLength * N + ps * mean_resultant_length(lambda_s) * mirror) / total;
}

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

TexelMoments texel_moments(bool valid, glm::vec3 P, glm::vec3 N, glm::vec3 diffuse, glm::vec3 specular,
                           float roughness, float pdf, glm::vec3 source_pos, bool camera_view) {
  TexelMoments m;
  if (!valid) return m;
  const glm::vec3 phi = diffuse + specular;
  const float w = camera_view ? luminance(phi) : phi.r + phi.g + phi.b;
  const glm::vec3 rbar = texel_emission_lobe(P, N, diffuse, specular, roughness, source_pos);
  m.m0 = glm::vec4(phi, w);
  m.m1 = glm::vec4(w * P, w * glm::dot(P, P));
  m.m2 = glm::vec4(w * rbar, pdf);
  return m;
}

VsglRecord vsgl_from_moments(glm::vec4 m0, glm::vec4 m1, glm::vec4 m2, glm::vec3 power, float level,
                             glm::vec2 center, float density, float texel_count) {
  VsglRecord v;
  v.center_pdf = glm::vec4(center, density, texel_count);
  const float W = m0.w;
  if (!(W > 0.0f)) {
    v.position_variance = glm::vec4(0.0f, 0.0f, 0.0f, kMinVariance);
    v.power_sharpness = glm::vec4(0.0f);
    v.axis_level = glm::vec4(0.0f, 0.0f, 1.0f, level);
    return v;
  }
  const glm::vec3 mu = glm::vec3(m1) / W;
  const float sigma2 = std::max((m1.w / W - glm::dot(mu, mu)) * 0.5f, kMinVariance);
  const glm::vec3 mean_dir = glm::vec3(m2) / W;
  const float len = glm::length(mean_dir);
  const glm::vec3 axis = len > 0.0f ? mean_dir / len : glm::vec3(0.0f, 0.0f, 1.0f);
  const float lambda = banerjee_sharpness(std::min(len, kMaxMeanLength));
  v.position_variance = glm::vec4(mu, sigma2);
  v.power_sharpness = glm::vec4(power, lambda);
  v.axis_level = glm::vec4(axis, level);
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
  view.lambda_v = 2.0f / one_minus_cos;
  view.scale = 2.0f / (kPi * r2);
  return view;
}

glm::vec3 vsgl_radiance_surface(const VsglRecord& v, glm::vec3 x, glm::vec3 n, glm::vec3 wo, glm::vec3 rho_d,
                                glm::vec3 rho_s, float roughness) {
  const VsglView view = vsgl_view_from(v, x, n);
  const glm::vec3 phi = v.power();
  const float lambda = v.sharpness();
  const glm::vec3 emit_axis = -v.axis();
  const float emission = sg_normalization(lambda) * view.scale;

  const float diffuse_term = kCosineSgAmplitude / kPi *
      sg_triple_integral(emit_axis, lambda, n, kCosineSgSharpness, view.wc, view.lambda_v);

  const float alpha = std::max(roughness, kMinRoughness);
  const float s_r = (2.0f / (alpha * alpha)) / (4.0f * std::max(glm::dot(n, wo), kMinCosine));
  const glm::vec3 axis_r = glm::reflect(-wo, n);
  const float specular_term = std::max(glm::dot(axis_r, n), 0.0f) / sg_integral(s_r) *
      sg_triple_integral(emit_axis, lambda, axis_r, s_r, view.wc, view.lambda_v);

  return phi * (emission * (rho_d * diffuse_term + rho_s * specular_term));
}

float vsgl_importance_to_vpl(const VsglRecord& cam, glm::vec3 x, glm::vec3 vpl_axis, float vpl_lambda) {
  const VsglView view = vsgl_view_from(cam, x, vpl_axis);
  const glm::vec3 phi = cam.power();
  const float lambda = cam.sharpness();
  const float emission = (phi.r + phi.g + phi.b) * sg_normalization(lambda) * view.scale;
  return emission * sg_normalization(vpl_lambda) *
      sg_triple_integral(-cam.axis(), lambda, vpl_axis, vpl_lambda, view.wc, view.lambda_v);
}

}  // namespace vsgl
