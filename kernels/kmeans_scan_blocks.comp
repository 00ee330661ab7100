#version 450
#extension GL_GOOGLE_include_directive : require
// Exclusive prefix sum of uints, level k of a multi-level scan (used by the radix sort's digit
// histograms and the grid's cell counts): each group scans one block of GROUP * ITEMS values in place
// and writes the block's total to level k+1 (in the aux buffer). kmeans_scan_add.comp then adds
// the scanned totals back. Integer sums: the result is exact and order-independent.
#include "kmeans_common.glsl"
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansWideGroupSize (interface/kmeans.h)
layout(std430, binding = 0) buffer Target { uint target_words[]; };
layout(std430, binding = 1) buffer Aux { uint aux_words[]; };
layout(push_constant) uniform PushBlock { KmeansScanPush pc; };

const uint ITEMS = kKmeansScanItems;
const uint GROUP = gl_WorkGroupSize.x;
shared uint partial[GROUP];

uint load(uint i) {
  if (i >= pc.count) return 0u;
  return pc.in_aux != 0u ? aux_words[pc.in_offset + i] : target_words[pc.in_offset + i];
}
void store(uint i, uint v) {
  if (i >= pc.count) return;
  if (pc.in_aux != 0u) aux_words[pc.in_offset + i] = v; else target_words[pc.in_offset + i] = v;
}

void main() {
  uint block = kmeans_flat_group();
  uint t = gl_LocalInvocationIndex;
  uint base = block * GROUP * ITEMS + t * ITEMS;
  uint v[ITEMS];
  uint sum = 0u;
  for (uint k = 0u; k < ITEMS; ++k) {
    v[k] = load(base + k);
    sum += v[k];
  }
  // Inclusive scan of the GROUP thread sums (Hillis-Steele).
  partial[t] = sum;
  barrier();
  for (uint stride = 1u; stride < GROUP; stride <<= 1u) {
    uint add = t >= stride ? partial[t - stride] : 0u;
    barrier();
    partial[t] += add;
    barrier();
  }
  uint running = partial[t] - sum;  // exclusive prefix of this thread
  for (uint k = 0u; k < ITEMS; ++k) {
    store(base + k, running);
    running += v[k];
  }
  // (Groups beyond the last block exist only when the dispatch was folded into rows.)
  if (t == GROUP - 1u && block * GROUP * ITEMS < pc.count) aux_words[pc.out_offset + block] = partial[GROUP - 1u];
}
