#version 450
#extension GL_GOOGLE_include_directive : require
// After the sort: each cluster's [begin, end) in the sorted pairs, by binary search of its key
// and the next (an empty cluster gets begin == end at its place in the order). One thread per cluster.
#include "kmeans_common.glsl"
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansNarrowGroupSize (interface/kmeans.h)
layout(std430, binding = 0) readonly buffer Sorted { uvec2 sorted_pairs[]; };
layout(std430, binding = 1) writeonly buffer Ranges { uvec2 ranges[]; };
layout(push_constant) uniform PushBlock { KmeansRangesPush pc; };

// First position whose key is >= key.
uint lower_bound(uint key) {
  uint lo = 0u, hi = pc.count;
  while (lo < hi) {
    uint mid = lo + (hi - lo) / 2u;
    if (kmeans_sort_key(sorted_pairs[mid].x, pc.clusters) < key) lo = mid + 1u; else hi = mid;
  }
  return lo;
}

void main() {
  uint k = kmeans_flat_invocation();
  if (k >= pc.clusters) return;
  ranges[k] = uvec2(lower_bound(k), lower_bound(k + 1u));
}
