#version 450
#extension GL_GOOGLE_include_directive : require
// The push of the ISMs' pull-push hole filling (DESIGN.md §8a.2; Ritschel et al. 2008): thread
// (f, m) fills texel f of map m's fine level, if no point and no pull gave it a distance, with
// the bilinear interpolation of the coarse level (already filled, one dispatch per level from the
// coarsest) at its centre; taps that are still empty (a map without any point) are left out and
// the weights of the others renormalized. Texels that hold a distance are not touched.
#include "interface/ism.h"

layout(local_size_x_id = 0) in;  // kIsmGroupSize (interface/ism.h); y: the map

layout(std430, binding = 0) buffer Maps { uint depths[]; };
layout(push_constant) uniform PushBlock { IsmPyramidPush pc; };

void main() {
  uint f = gl_GlobalInvocationID.x;
  uint m = gl_GlobalInvocationID.y;
  if (f >= pc.fine_side * pc.fine_side || m >= pc.map_count) return;
  uint at = m * pc.map_stride + pc.fine_offset + f;
  if (depths[at] != kIsmEmpty) return;
  int coarse_side = int(pc.fine_side / 2u);
  // The fine texel's centre in coarse texel units, less the half texel of the coarse centres.
  vec2 u = (vec2(f % pc.fine_side, f / pc.fine_side) + 0.5) * 0.5 - 0.5;
  ivec2 i0 = ivec2(floor(u));
  vec2 w = u - vec2(i0);
  uint coarse = m * pc.map_stride + pc.coarse_offset;
  float sum = 0.0;
  float weight = 0.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k % 2, k / 2);
    ivec2 tap = clamp(i0 + o, ivec2(0), ivec2(coarse_side - 1));
    uint bits = depths[coarse + uint(tap.y * coarse_side + tap.x)];
    if (bits == kIsmEmpty) continue;
    float wk = (o.x == 1 ? w.x : 1.0 - w.x) * (o.y == 1 ? w.y : 1.0 - w.y);
    sum += wk * uintBitsToFloat(bits);
    weight += wk;
  }
  if (weight > 0.0) depths[at] = floatBitsToUint(sum / weight);
}
