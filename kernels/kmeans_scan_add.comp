#version 450
#extension GL_GOOGLE_include_directive : require
// Multi-level exclusive scan, downward step: adds the scanned block totals of level k+1 to every
// element of level k's blocks (see kmeans_scan_blocks.comp).
#include "kmeans_common.glsl"
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansWideGroupSize (interface/kmeans.h)
layout(std430, binding = 0) buffer Target { uint target_words[]; };
layout(std430, binding = 1) buffer Aux { uint aux_words[]; };
layout(push_constant) uniform PushBlock { KmeansScanPush pc; };

const uint ITEMS = kKmeansScanItems;
const uint GROUP = gl_WorkGroupSize.x;

void main() {
  uint block = kmeans_flat_group();
  if (block * GROUP * ITEMS >= pc.count) return;
  uint add = aux_words[pc.out_offset + block];  // the scanned block totals (aux buffer)
  uint base = block * GROUP * ITEMS + gl_LocalInvocationIndex * ITEMS;
  for (uint k = 0u; k < ITEMS; ++k) {
    uint i = base + k;
    if (i >= pc.count) return;
    if (pc.in_aux != 0u) aux_words[pc.in_offset + i] += add; else target_words[pc.in_offset + i] += add;
  }
}
