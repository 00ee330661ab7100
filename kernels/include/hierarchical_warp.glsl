#ifndef HIERARCHICAL_WARP_GLSL
#define HIERARCHICAL_WARP_GLSL
// Kernel centres (SPEC §5): a Fibonacci lattice warped down the PDF pyramid (layer 2, .w = q).
// C++ twin: reference_samples() in harness/fis_reference.cpp, float for float.
#include "pyramid.glsl"

const uint PDF_LAYER = 2u;

// u_i = ((i + 0.5) / N, frac(i / phi + o)). The second coordinate is formed in 32-bit fixed point
// (2654435769 = 2^32 / phi), so it is exact for any i and identical on every device.
vec2 fibonacci_lattice(uint i, uint n, uint offset_bits) {
  uint y = i * 2654435769u + offset_bits;
  return vec2((float(i) + 0.5) / float(n), float(y >> 8u) * (1.0 / 16777216.0));
}

struct WarpedSample {
  ivec2 texel;  // level-0 texel
  vec2 x;       // position in [0,1]^2 of the virtual square
  float pdf;    // p(x) = q(texel) / q_L
};

const float ONE_MINUS_ULP = 0.99999994;  // largest float below 1

float pdf_weight(uint level, ivec2 p) { return pyramid_texel(PDF_LAYER, level, p).w; }

// Hierarchical sample warping: from the 1x1 level down, pick the column by the sums of the 2x2
// children, rescale u.x into it, then the child within the column, rescale u.y. The same u is
// reused all the way down, which keeps the lattice's stratification. Zero-mass children are
// never entered: u < 0 is false and u < 1 is true.
WarpedSample warp_sample(vec2 u) {
  ivec2 cur = ivec2(0);
  for (int k = int(pyramid_levels); k >= 1; --k) {
    uint child = uint(k - 1);
    ivec2 c = cur * 2;
    precise float left = pdf_weight(child, c) + pdf_weight(child, c + ivec2(0, 1));
    precise float right = pdf_weight(child, c + ivec2(1, 0)) + pdf_weight(child, c + ivec2(1, 1));
    precise float pl = left / (left + right);
    int col;
    if (u.x < pl) {
      col = c.x;
      u.x = u.x / pl;
    } else {
      col = c.x + 1;
      u.x = (u.x - pl) / (1.0 - pl);
    }
    u.x = clamp(u.x, 0.0, ONE_MINUS_ULP);
    precise float top = pdf_weight(child, ivec2(col, c.y));
    precise float bottom = pdf_weight(child, ivec2(col, c.y + 1));
    precise float pt = top / (top + bottom);
    int row;
    if (u.y < pt) {
      row = c.y;
      u.y = u.y / pt;
    } else {
      row = c.y + 1;
      u.y = (u.y - pt) / (1.0 - pt);
    }
    u.y = clamp(u.y, 0.0, ONE_MINUS_ULP);
    cur = ivec2(col, row);
  }
  WarpedSample s;
  s.texel = cur;
  s.x = (vec2(cur) + u) / float(pyramid_size);
  s.pdf = pdf_weight(0u, cur) / pdf_weight(pyramid_levels, ivec2(0));
  return s;
}

#endif
