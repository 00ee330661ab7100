#version 450
#extension GL_GOOGLE_include_directive : require
// k-means centre update (DESIGN.md §6.2, end of each Lloyd iteration), step 1 of 2: a deterministic
// segmented reduction over the assignment sorted by cluster. The sorted order is cut into chunks
// of CHUNK elements; thread j sums, sequentially, the (q f, q) of each cluster's elements inside
// chunk j and stores the piece of cluster k at slot j + k (slots are unique: a cluster's chunks
// are consecutive and the next cluster starts in the same or a later chunk, one slot further).
// Fixed order, no float atomics: the centres are reproducible run to run, and the CPU reference
// (kmeans_update_centres in harness/reference/kmeans_reference.cpp) repeats the same order bit for bit.
#include "kmeans_common.glsl"
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansNarrowGroupSize (interface/kmeans.h)
layout(std430, binding = 0) readonly buffer Sorted { uvec2 sorted_pairs[]; };
layout(std430, binding = 1) readonly buffer Features { vec4 features[]; };
layout(std430, binding = 2) writeonly buffer Pieces { vec4 pieces[]; };
layout(push_constant) uniform PushBlock { KmeansPiecesPush pc; };

vec4 weighted_feature(uint texel) {
  vec4 f = features[texel];
  precise vec4 v = vec4(f.xyz * f.w, f.w);
  return v;
}

void main() {
  uint j = kmeans_flat_invocation();
  uint begin = j * pc.chunk;
  if (begin >= pc.count) return;
  uint end = min(begin + pc.chunk, pc.count);
  uint cluster = KMEANS_NO_CLUSTER;
  precise vec4 sum = vec4(0.0);
  for (uint i = begin; i < end; ++i) {
    uvec2 pair = sorted_pairs[i];
    if (pair.x == KMEANS_NO_CLUSTER) break;  // the unclustered texels sort last
    if (pair.x != cluster) {
      if (cluster != KMEANS_NO_CLUSTER) pieces[j + cluster] = sum;
      cluster = pair.x;
      sum = weighted_feature(pair.y);
    } else {
      sum = sum + weighted_feature(pair.y);
    }
  }
  if (cluster != KMEANS_NO_CLUSTER) pieces[j + cluster] = sum;
}
