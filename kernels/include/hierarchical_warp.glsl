#ifndef HIERARCHICAL_WARP_GLSL
#define HIERARCHICAL_WARP_GLSL
// Kernel centres (DESIGN.md §5): a Fibonacci lattice warped down the PDF pyramid (layer 2, .w = q).
// C++ twin: reference_samples() in harness/reference/fis_reference.cpp, float for float.
// The includer chooses the pyramid's accessors first: pyramid.glsl (storage buffer) or
// pyramid_texture.glsl (sampled image, DESIGN.md §6.1a).
#ifndef PYRAMID_ACCESSORS
#error "include pyramid.glsl or pyramid_texture.glsl before hierarchical_warp.glsl"
#endif

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

// One binary decision: the first child with probability first / (first + second), u rescaled into
// the chosen part so it can be reused below. `precise` keeps the CPU twin's rounding.
bool warp_choose_first(inout float u, float first, float second) {
  precise float p = first / (first + second);
  bool take_first = u < p;
  precise float rescaled = take_first ? u / p : (u - p) / (1.0 - p);
  u = clamp(rescaled, 0.0, ONE_MINUS_ULP);
  return take_first;
}

// Hierarchical sample warping: from the 1x1 level down, pick the column by the sums of the 2x2
// children, rescale u.x into it, then the child within the column, rescale u.y. The same u is
// reused all the way down, which keeps the lattice's stratification. Zero-mass children are
// never entered: u < 0 is false and u < 1 is true.
WarpedSample warp_sample(vec2 u) {
  ivec2 cur = ivec2(0);
  for (int k = int(pyramid_levels); k >= 1; --k) {
    uint child = uint(k - 1);
    ivec2 c = cur * 2;
    float left = pdf_weight(child, c) + pdf_weight(child, c + ivec2(0, 1));
    float right = pdf_weight(child, c + ivec2(1, 0)) + pdf_weight(child, c + ivec2(1, 1));
    int col = warp_choose_first(u.x, left, right) ? c.x : c.x + 1;
    float top = pdf_weight(child, ivec2(col, c.y));
    float bottom = pdf_weight(child, ivec2(col, c.y + 1));
    int row = warp_choose_first(u.y, top, bottom) ? c.y : c.y + 1;
    cur = ivec2(col, row);
  }
  WarpedSample s;
  s.texel = cur;
  s.x = (vec2(cur) + u) / float(pyramid_size);
  s.pdf = pdf_weight(0u, cur) / pdf_weight(pyramid_levels, ivec2(0));
  return s;
}

#endif
