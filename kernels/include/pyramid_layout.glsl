#ifndef PYRAMID_LAYOUT_GLSL
#define PYRAMID_LAYOUT_GLSL
// The virtual square of DESIGN.md §4 (C++ twin harness/math/virtual_square.hpp): S, L, each level's
// in-bounds extent and, for the buffer path, each level's offset in a layer. Shared by both
// pyramid paths (pyramid.glsl: storage buffer; pyramid_texture.glsl: sampled image).
// Call pyramid_init() first in main().

uint pyramid_width;    // W
uint pyramid_height;   // H
uint pyramid_size;     // S = next pow2 >= max(W, H)
uint pyramid_levels;   // L = log2 S
uint pyramid_total;    // texels of all levels of one layer
uint pyramid_offset[16];

uint pyramid_level_width(uint l) { return ((pyramid_width - 1u) >> l) + 1u; }
uint pyramid_level_height(uint l) { return ((pyramid_height - 1u) >> l) + 1u; }

void pyramid_init(uint width, uint height) {
  pyramid_width = width;
  pyramid_height = height;
  uint side = max(width, height);
  pyramid_size = 1u;
  pyramid_levels = 0u;
  while (pyramid_size < side) {
    pyramid_size <<= 1u;
    ++pyramid_levels;
  }
  uint offset = 0u;
  for (uint l = 0u; l <= pyramid_levels; ++l) {
    pyramid_offset[l] = offset;
    offset += pyramid_level_width(l) * pyramid_level_height(l);
  }
  pyramid_total = offset;
}

// A level-(l+1) texel from its four children (missing children are zero), summed in this fixed
// order so every mipmapping kernel and the CPU reference (MipPyramid::build) agree bit for bit.
vec4 mip_average(vec4 c00, vec4 c10, vec4 c01, vec4 c11) {
  precise vec4 sum = c00 + c10;
  sum = sum + c01;
  sum = sum + c11;
  return sum * 0.25;
}

#endif
