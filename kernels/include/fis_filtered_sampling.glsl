#ifndef FIS_FILTERED_SAMPLING_GLSL
#define FIS_FILTERED_SAMPLING_GLSL
// FIS phase 3, "filtered sampling", shared by both pyramid paths: one thread per VSGL i. Sample the
// kernel centre x_i (DESIGN.md §5), choose its mip level l_i, fetch the moments at (x_i, l_i) and build
// the VSGL (DESIGN.md §7). FIS_VARIANT selects [Tok15] (Eq. 1, Eq. 4) or the modified FIS (Eq. 3,
// Eq. 5); the two share everything but choose_level() and estimate_power() below.
// The includer has chosen the pyramid's accessors (pyramid.glsl or pyramid_texture.glsl) and
// declared `vsgls`. Every pyramid_trilinear() is one lookup: 8 buffer taps on the buffer path,
// one textureLod on the texture path.
#include "interface/fis.h"
#include "hierarchical_warp.glsl"
#include "vsgl_math.glsl"

layout(local_size_x_id = 0) in;
layout(constant_id = 1) const uint FIS_VARIANT = 1u;  // 0: [Tok15], 1: modified (the paper's "Ours")
// table3: begin modified
layout(constant_id = 2) const uint BISECTION_ITERATIONS = 12u;
// table3: end modified

layout(push_constant) uniform PushBlock { FisSamplingPush pc; };

float square_texels() { return float(pyramid_size) * float(pyramid_size); }  // M

// table3: begin modified
// a(l) * p_bar(x, l): the PDF mass inside a level-l kernel centred at x (left side of Eq. 3).
float kernel_mass(vec2 x, float level, float q_top) {
  return exp2(2.0 * level) / square_texels() * (pyramid_trilinear(PDF_LAYER, x, level).w / q_top);
}
// table3: end modified

// ---- [Tok15] vs modified FIS: the only two places they differ --------------------------------
// The regions are the lines each specialization keeps (Table 3 counts them per variant).
float choose_level(WarpedSample s, float q_top) {
  float L = float(pyramid_levels);
  // table3: begin tok15
  if (FIS_VARIANT == 0u) {
    // Eq. 1: 4^l / M = min(K / (N p(x_i)), 1).
    return clamp(0.5 * log2(pc.K * square_texels() / (float(pc.count) * s.pdf)), 0.0, L);
  }
  // table3: end tok15
  // table3: begin modified
  // Eq. 3 with K: solve a(l) p_bar(x_i, l) = K / N by bisection on [0, L].
  float target = pc.K / float(pc.count);
  if (kernel_mass(s.x, 0.0, q_top) >= target) return 0.0;
  float lo = 0.0, hi = L;
  for (uint it = 0u; it < BISECTION_ITERATIONS; ++it) {
    float mid = 0.5 * (lo + hi);
    if (kernel_mass(s.x, mid, q_top) < target) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
  // table3: end modified
}

// Returns the factor that turns the filtered mean flux into the cluster's power (Eq. 4 / Eq. 5);
// `density` receives the PDF value the estimator divided by.
float power_scale(WarpedSample s, float level, float q_top, out float density) {
  float N = float(pc.count);
  // table3: begin tok15
  if (FIS_VARIANT == 0u) {
    density = s.pdf;  // Eq. 4: the numerator is filtered, the denominator is not
    return square_texels() / max(N * s.pdf, pc.K);
  }
  // table3: end tok15
  // table3: begin modified
  density = pyramid_trilinear(PDF_LAYER, s.x, level).w / q_top;  // Eq. 5: both filtered alike
  return square_texels() / (N * density);
  // table3: end modified
}
// ------------------------------------------------------------------------------------------------

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  pyramid_init(pc.width, pc.height);
  float q_top = pdf_weight(pyramid_levels, ivec2(0));
  WarpedSample s = warp_sample(fibonacci_lattice(i, pc.count, pc.offset_bits));
  float level = choose_level(s, q_top);
  vec4 m0 = pyramid_trilinear(0u, s.x, level);
  vec4 m1 = pyramid_trilinear(1u, s.x, level);
  vec4 m2 = pyramid_trilinear(2u, s.x, level);
  vec4 m3 = pyramid_trilinear(3u, s.x, level);
  vec4 m4 = pyramid_trilinear(4u, s.x, level);
  float density;
  float scale = power_scale(s, level, q_top, density);
  vsgls[i] = vsgl_from_moments(m0, m1, m2, m3, m4, scale, level, s.x, density, 0.0);
}

#endif
