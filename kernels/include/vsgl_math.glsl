#ifndef VSGL_MATH_GLSL
#define VSGL_MATH_GLSL
// The maths of a VSGL (DESIGN.md §4, §7): per-texel moments (the "additional" pass), a texel's
// specular lobe as an averaged direction, and a VSGL built from filtered or summed moments.
// C++ twin: harness/math/vsgl_math.hpp (same formulas, same branches; tests/test_vsgl_math_glsl.cpp
// compares the two). Formulas and constants: kernels/CONVENTIONS.md, shared with the CPU reference.

const float VSGL_PI = 3.14159265358979;
const float VSGL_MAX_SHARPNESS = 1e4;
const float VSGL_MAX_MEAN_LENGTH = 0.9999;
const float VSGL_MIN_VARIANCE = 1e-8;   // epsilon of sigma^2 (so r^2 >= 2e-8)
const float VSGL_MIN_ROUGHNESS = 1e-3;  // GGX alpha floor
const float VSGL_MIN_COSINE = 1e-4;     // floor of the cosine in the reflection-lobe warp

// A(lambda) = coth(lambda) - 1/lambda: the mean resultant length |E[w]| of a vMF/SG lobe of
// sharpness lambda. Branches keep float32 accurate: the series below 0.5 avoids the cancellation
// of coth - 1/lambda (which loses ~20% at lambda = 1e-3 in float), coth is formed from
// exp(-2 lambda) (no overflow), and above 20 coth(lambda) = 1 to float precision.
float mean_resultant_length(float lambda) {
  if (lambda < 1e-3) return lambda / 3.0;
  if (lambda < 0.5) {
    // coth x - 1/x = x/3 - x^3/45 + 2x^5/945 - x^7/4725 + O(x^9)
    float l2 = lambda * lambda;
    return lambda * (1.0 / 3.0 - l2 * (1.0 / 45.0 - l2 * (2.0 / 945.0 - l2 * (1.0 / 4725.0))));
  }
  if (lambda > 20.0) return 1.0 - 1.0 / lambda;
  float e = exp(-2.0 * lambda);
  return (1.0 + e) / (1.0 - e) - 1.0 / lambda;
}

// Banerjee et al.'s approximate inverse of A: lambda = r (3 - r^2) / (1 - r^2), with r limited to
// [0, 0.9999] and lambda to [0, 1e4].
float banerjee_sharpness(float r) {
  float rc = clamp(r, 0.0, VSGL_MAX_MEAN_LENGTH);
  float r2 = rc * rc;
  return clamp(rc * (3.0 - r2) / (1.0 - r2), 0.0, VSGL_MAX_SHARPNESS);
}

// The SG NDF sharpness 2/alpha^2 warped to the reflection lobe about a direction at cosine cos_n to the
// normal (Wang et al. 2009), alpha floored at 1e-3, the cosine at 1e-4, clamped to [0, 1e4]: the
// specular lobe of a texel (toward its source) and of a receiver (toward its viewer) alike.
float reflection_lobe_sharpness(float roughness, float cos_n) {
  float alpha = max(roughness, VSGL_MIN_ROUGHNESS);
  return clamp((2.0 / (alpha * alpha)) / (4.0 * max(cos_n, VSGL_MIN_COSINE)), 0.0, VSGL_MAX_SHARPNESS);
}

// The specular lobe of a texel lit (or seen) from source_pos as an averaged direction (Tok15 §3.2,
// Toksvig): A(lambda_s) * reflect(-omega_in, N), a normalized SG whose mean direction vector
// mipmaps linearly. lambda_s warps the SG NDF sharpness 2/alpha^2 to the reflection lobe (Wang et
// al. 2009). The diffuse lobe needs no direction: Tok15 makes it an SG of zero sharpness, so its
// coefficient alone is stored (DESIGN.md §7).
vec3 texel_specular_direction(vec3 P, vec3 N, float roughness, vec3 source_pos) {
  vec3 to_source = source_pos - P;
  float dist2 = dot(to_source, to_source);
  // A source on the texel itself has no direction; fall back to the normal (no NaN).
  vec3 omega_in = dist2 > 0.0 ? to_source * inversesqrt(dist2) : N;
  return mean_resultant_length(reflection_lobe_sharpness(roughness, dot(N, omega_in))) * reflect(-omega_in, N);
}

// Rec. 709 luminance: the camera view's power weight w and PDF.
float vsgl_luminance(vec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// The five moment layers of one texel (DESIGN.md §4, §6.1 "additional"; Tok15 §3.2's RSM), all zero
// when invalid:
//   m0 = (Phi.rgb, w), m1 = (w P, w |P|^2), m2 = (w N, q), m3 = (Phi_s.rgb, 0), m4 = (s d_s, 0)
// with Phi = diffuse + specular, Phi_s the specular part, s = Phi_s.r + Phi_s.g + Phi_s.b and d_s
// the specular lobe's averaged direction (weighted by s, so a texel without a specular part does not
// shorten the filtered lobe).
// Light view: Phi = diffuse + specular flux, w = Phi.r + Phi.g + Phi.b, source = spot light.
// Camera view: Phi = diffuse + specular albedo (importance), w = luminance(Phi), source = camera.
void texel_moments(bool valid, vec3 P, vec3 N, vec3 diffuse, vec3 specular, float roughness, float pdf,
                   vec3 source_pos, bool camera_view, out vec4 m0, out vec4 m1, out vec4 m2, out vec4 m3,
                   out vec4 m4) {
  if (!valid) {
    m0 = vec4(0.0);
    m1 = vec4(0.0);
    m2 = vec4(0.0);
    m3 = vec4(0.0);
    m4 = vec4(0.0);
    return;
  }
  vec3 phi = diffuse + specular;
  float w = camera_view ? vsgl_luminance(phi) : phi.r + phi.g + phi.b;
  float s = specular.r + specular.g + specular.b;
  m0 = vec4(phi, w);
  m1 = vec4(w * P, w * dot(P, P));
  m2 = vec4(w * N, pdf);
  m3 = vec4(specular, 0.0);
  m4 = vec4(s > 0.0 ? s * texel_specular_direction(P, N, roughness, source_pos) : vec3(0.0), 0.0);
}

// The GPU output record of every generator (std430, 96 bytes; C++: VsglRecord). Tok15 Eq. 3 with
// K = 2 needs the filtered normal (the exact cosine at the light), the diffuse and specular power
// and the specular lobe (DESIGN.md §7).
struct Vsgl {
  vec4 position_variance;  // mu.xyz, sigma^2 = E|x|^2 - |E x|^2 (r^2 = 2 sigma^2)
  vec4 power_sharpness;    // Phi.rgb (diffuse + specular), lambda of the specular lobe
  vec4 axis_level;         // specular lobe axis.xyz, level l_i (FIS) or -1 (k-means)
  vec4 center_pdf;         // kernel centre x_i.xy, density used in the power, texel count (k-means) else 0
  vec4 normal_length;      // filtered normal (unit).xyz, |E N| (1: all normals agree)
  vec4 specular_power;     // Phi_s.rgb (part of Phi), 0
};

// A VSGL from the moments of one kernel or cluster (DESIGN.md §7). The moments may be means (FIS
// fetches) or sums (k-means): positions, normals and the lobe use only ratios, and the power is
// power_scale * m0.rgb (specular part power_scale * m3.rgb). W = m0.w <= 0 gives a VSGL of zero power.
Vsgl vsgl_from_moments(vec4 m0, vec4 m1, vec4 m2, vec4 m3, vec4 m4, float power_scale, float level, vec2 center,
                       float density, float texel_count) {
  Vsgl v;
  v.center_pdf = vec4(center, density, texel_count);
  float W = m0.w;
  if (!(W > 0.0)) {
    v.position_variance = vec4(0.0, 0.0, 0.0, VSGL_MIN_VARIANCE);
    v.power_sharpness = vec4(0.0);
    v.axis_level = vec4(0.0, 0.0, 1.0, level);
    v.normal_length = vec4(0.0, 0.0, 1.0, 0.0);
    v.specular_power = vec4(0.0);
    return v;
  }
  vec3 mu = m1.xyz / W;
  // Tok15 §3.2: sigma^2 = E|x|^2 - |E x|^2 and r^2 = 2 sigma^2, the radius of a uniform disk.
  float sigma2 = max(m1.w / W - dot(mu, mu), VSGL_MIN_VARIANCE);
  vec3 mean_normal = m2.xyz / W;
  float normal_len = length(mean_normal);
  vec3 normal = normal_len > 0.0 ? mean_normal / normal_len : vec3(0.0, 0.0, 1.0);
  float s = m3.r + m3.g + m3.b;
  vec3 mean_dir = s > 0.0 ? m4.xyz / s : vec3(0.0);
  float len = length(mean_dir);
  vec3 axis = len > 0.0 ? mean_dir / len : normal;
  float lambda = banerjee_sharpness(min(len, VSGL_MAX_MEAN_LENGTH));
  v.position_variance = vec4(mu, sigma2);
  v.power_sharpness = vec4(power_scale * m0.rgb, lambda);
  v.axis_level = vec4(axis, level);
  v.normal_length = vec4(normal, normal_len);
  v.specular_power = vec4(power_scale * m3.rgb, 0.0);
  return v;
}

#endif  // VSGL_MATH_GLSL
