#ifndef VSGL_MATH_GLSL
#define VSGL_MATH_GLSL
// The maths of a VSGL (DESIGN.md §4, §7): per-texel moments (the "additional" pass), the lobe of a
// texel as a mean direction vector, and a VSGL built from filtered or summed moments.
// C++ twin: harness/math/vsgl_math.hpp (same formulas, same branches; tests/test_vsgl_math_glsl.cpp
// compares the two). Formulas and constants: kernels/CONVENTIONS.md, shared with the CPU reference.

const float VSGL_PI = 3.14159265358979;
// Mean resultant length of the vMF lobe approximating a clamped cosine (lambda ~= 2.29 under the
// Banerjee formula below), used for the diffuse part of a texel's lobe (DESIGN.md §7).
const float VSGL_DIFFUSE_MEAN_LENGTH = 0.575;
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

// rbar: the emission lobe of a texel lit (or seen) from source_pos, as a mean direction vector
// (DESIGN.md §7): the diffuse part A_d * N and the glossy part A(lambda_s) * reflect(-omega_in, N),
// weighted by the diffuse and specular channel sums. lambda_s warps the SG NDF sharpness 2/alpha^2
// to the reflection lobe (Wang et al. 2009). Zero when the texel reflects nothing.
vec3 texel_emission_lobe(vec3 P, vec3 N, vec3 diffuse, vec3 specular, float roughness, vec3 source_pos) {
  float pd = diffuse.r + diffuse.g + diffuse.b;
  float ps = specular.r + specular.g + specular.b;
  float total = pd + ps;
  if (!(total > 0.0)) return vec3(0.0);
  vec3 to_source = source_pos - P;
  float dist2 = dot(to_source, to_source);
  // A source on the texel itself has no direction; fall back to the normal (no NaN).
  vec3 omega_in = dist2 > 0.0 ? to_source * inversesqrt(dist2) : N;
  float alpha = max(roughness, VSGL_MIN_ROUGHNESS);
  float cos_in = dot(N, omega_in);
  float lambda_s = clamp((2.0 / (alpha * alpha)) / (4.0 * max(cos_in, VSGL_MIN_COSINE)), 0.0, VSGL_MAX_SHARPNESS);
  vec3 mirror = reflect(-omega_in, N);
  return (pd * VSGL_DIFFUSE_MEAN_LENGTH * N + ps * mean_resultant_length(lambda_s) * mirror) / total;
}

// Rec. 709 luminance: the camera view's power weight w and PDF.
float vsgl_luminance(vec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// The three moment layers of one texel (DESIGN.md §4, §6.1 "additional"), all zero when invalid:
//   m0 = (Phi.rgb, w), m1 = (w P, w |P|^2), m2 = (w rbar, q).
// Light view: Phi = diffuse + specular flux, w = Phi.r + Phi.g + Phi.b, source = spot light.
// Camera view: Phi = diffuse + specular albedo (importance), w = luminance(Phi), source = camera.
void texel_moments(bool valid, vec3 P, vec3 N, vec3 diffuse, vec3 specular, float roughness, float pdf,
                   vec3 source_pos, bool camera_view, out vec4 m0, out vec4 m1, out vec4 m2) {
  if (!valid) {
    m0 = vec4(0.0);
    m1 = vec4(0.0);
    m2 = vec4(0.0);
    return;
  }
  vec3 phi = diffuse + specular;
  float w = camera_view ? vsgl_luminance(phi) : phi.r + phi.g + phi.b;
  vec3 rbar = texel_emission_lobe(P, N, diffuse, specular, roughness, source_pos);
  m0 = vec4(phi, w);
  m1 = vec4(w * P, w * dot(P, P));
  m2 = vec4(w * rbar, pdf);
}

// The GPU output record of every generator (std430, 64 bytes; C++: VsglRecord).
struct Vsgl {
  vec4 position_variance;  // mu.xyz, sigma^2
  vec4 power_sharpness;    // Phi.rgb, lambda
  vec4 axis_level;         // lobe axis.xyz, level l_i (FIS) or -1 (k-means)
  vec4 center_pdf;         // kernel centre x_i.xy, density used in the power, texel count (k-means) else 0
};

// A VSGL from the moments of one kernel or cluster (DESIGN.md §7). The moments may be means (FIS
// fetches) or sums (k-means): only ratios to W = m0.w are used. W <= 0 gives a VSGL of zero power.
Vsgl vsgl_from_moments(vec4 m0, vec4 m1, vec4 m2, vec3 power, float level, vec2 center, float density,
                       float texel_count) {
  Vsgl v;
  v.center_pdf = vec4(center, density, texel_count);
  float W = m0.w;
  if (!(W > 0.0)) {
    v.position_variance = vec4(0.0, 0.0, 0.0, VSGL_MIN_VARIANCE);
    v.power_sharpness = vec4(0.0);
    v.axis_level = vec4(0.0, 0.0, 1.0, level);
    return v;
  }
  vec3 mu = m1.xyz / W;
  // Per-axis variance of points assumed on a plane (two axes): r^2 = 2 sigma^2 (Tok15 §3.2).
  float sigma2 = max((m1.w / W - dot(mu, mu)) * 0.5, VSGL_MIN_VARIANCE);
  vec3 mean_dir = m2.xyz / W;
  float len = length(mean_dir);
  vec3 axis = len > 0.0 ? mean_dir / len : vec3(0.0, 0.0, 1.0);
  float lambda = banerjee_sharpness(min(len, VSGL_MAX_MEAN_LENGTH));
  v.position_variance = vec4(mu, sigma2);
  v.power_sharpness = vec4(power, lambda);
  v.axis_level = vec4(axis, level);
  return v;
}

#endif  // VSGL_MATH_GLSL
