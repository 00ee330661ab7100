#ifndef PYRAMID_GLSL
#define PYRAMID_GLSL
#define PYRAMID_ACCESSORS
// The storage-buffer pyramid of DESIGN.md §4 with software filtering (`--pyramid buffer`).
// The includer declares the buffer `pyramid_texels` (vec4) holding kMomentLayers layers of
// `pyramid_total` texels each (texel_moments() in vsgl_math.glsl, DESIGN.md §4).
// pyramid_texture.glsl offers the same functions on a sampled image (DESIGN.md §6.1a).
#include "pyramid_layout.glsl"

// Texel (x, y) of a level; zero outside its in-bounds extent (the rest of the virtual square).
vec4 pyramid_texel(uint layer, uint level, ivec2 p) {
  if (p.x < 0 || p.y < 0 || uint(p.x) >= pyramid_level_width(level) || uint(p.y) >= pyramid_level_height(level))
    return vec4(0.0);
  return pyramid_texels[layer * pyramid_total + pyramid_offset[level] +
                        uint(p.y) * pyramid_level_width(level) + uint(p.x)];
}

// Bilinear within level k at x in [0,1]^2 of the square; taps outside read zero.
vec4 pyramid_bilinear(uint layer, vec2 x, uint k) {
  vec2 u = x * float(pyramid_size >> k) - 0.5;
  vec2 base = floor(u);
  vec2 f = u - base;
  ivec2 i0 = ivec2(base);
  return pyramid_texel(layer, k, i0) * ((1.0 - f.x) * (1.0 - f.y)) +
         pyramid_texel(layer, k, i0 + ivec2(1, 0)) * (f.x * (1.0 - f.y)) +
         pyramid_texel(layer, k, i0 + ivec2(0, 1)) * ((1.0 - f.x) * f.y) +
         pyramid_texel(layer, k, i0 + ivec2(1, 1)) * (f.x * f.y);
}

// Trilinear at a fractional level (DESIGN.md §4): numerator and denominator of Eq. 5 both go through it.
vec4 pyramid_trilinear(uint layer, vec2 x, float level) {
  float l0 = floor(level);
  uint k0 = uint(l0);
  uint k1 = min(k0 + 1u, pyramid_levels);
  return mix(pyramid_bilinear(layer, x, k0), pyramid_bilinear(layer, x, k1), level - l0);
}

#endif
