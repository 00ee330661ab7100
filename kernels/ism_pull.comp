#version 450
#extension GL_GOOGLE_include_directive : require
// The pull of the ISMs' pull-push hole filling (DESIGN.md §8a.2; Ritschel et al. 2008): thread
// (c, m) makes texel c of map m's coarse level the mean of the distances of its 2x2 children at
// the fine level that are not empty, or kIsmEmpty when all four are. The mean, not the minimum:
// on a surface it estimates the depth at the texel's centre without the minimum's pull toward the
// origin, which a depth bias would have to cover on every slanted receiver (DESIGN.md §8a.2).
#include "interface/ism.h"

layout(local_size_x_id = 0) in;  // kIsmGroupSize (interface/ism.h); y: the map

layout(std430, binding = 0) buffer Maps { uint depths[]; };
layout(push_constant) uniform PushBlock { IsmPyramidPush pc; };

void main() {
  uint c = gl_GlobalInvocationID.x;
  uint m = gl_GlobalInvocationID.y;
  uint coarse_side = pc.fine_side / 2u;
  if (c >= coarse_side * coarse_side || m >= pc.map_count) return;
  uint cx = c % coarse_side;
  uint cy = c / coarse_side;
  uint fine = m * pc.map_stride + pc.fine_offset;
  float sum = 0.0;
  uint count = 0u;
  for (uint k = 0u; k < 4u; ++k) {
    uint bits = depths[fine + (2u * cy + k / 2u) * pc.fine_side + 2u * cx + k % 2u];
    if (bits == kIsmEmpty) continue;
    sum += uintBitsToFloat(bits);
    ++count;
  }
  depths[m * pc.map_stride + pc.coarse_offset + c] = count > 0u ? floatBitsToUint(sum / float(count)) : kIsmEmpty;
}
