#ifndef PYRAMID_TEXTURE_GLSL
#define PYRAMID_TEXTURE_GLSL
#define PYRAMID_ACCESSORS
// The sampled-image pyramid of DESIGN.md §6.1a (`--pyramid texture`), with the functions of
// pyramid.glsl: the includer declares `pyramid_image`, a sampler2DArray over the S x S virtual
// square (array layers = moment layers 0..4; mip levels 0..L), whose sampler is LINEAR /
// LINEAR / mipmap LINEAR with a transparent-black border. Texels outside each level's in-bounds
// extent hold zero (cleared once when the image is made), so hardware filtering gives exactly the
// §4 semantics: zero outside the extent, level L the 1x1 mean.
#include "pyramid_layout.glsl"

// One texel of a level (no filtering). p must lie in the level's S_l x S_l square; the padding
// beyond the in-bounds extent reads zero.
vec4 pyramid_texel(uint layer, uint level, ivec2 p) {
  return texelFetch(pyramid_image, ivec3(p, int(layer)), int(level));
}

// Trilinear at a fractional level (DESIGN.md §4): one hardware-filtered lookup. Numerator and
// denominator of Eq. 5 both go through it, so they see the same filter weights.
vec4 pyramid_trilinear(uint layer, vec2 x, float level) {
  return textureLod(pyramid_image, vec3(x, float(layer)), level);
}

#endif
