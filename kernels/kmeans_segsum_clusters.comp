#version 450
#extension GL_GOOGLE_include_directive : require
// k-means `sum`, segmented-reduction variant, step 2 of 2: one thread per cluster adds its pieces
// (at most size / CHUNK + 1, in chunk order) and builds the VSGL (DESIGN.md §7).
#include "kmeans_common.glsl"
#include "vsgl_math.glsl"
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansNarrowGroupSize (interface/kmeans.h)
layout(std430, binding = 0) readonly buffer Ranges { uvec2 ranges[]; };
layout(std430, binding = 1) readonly buffer Pieces { vec4 pieces[]; };  // kKmeansPieceVec4s vec4 per slot
layout(std430, binding = 2) readonly buffer Centres { vec4 centres[]; };
layout(std430, binding = 3) writeonly buffer Vsgls { Vsgl vsgls[]; };
#include "kmeans_cluster.glsl"
#include "kmeans_sum_push.glsl"

ClusterMoments load_piece(uint slot) {
  ClusterMoments s;
  uint b = kKmeansPieceVec4s * slot;
  s.m0 = pieces[b];
  s.m1 = pieces[b + 1u];
  s.m2 = pieces[b + 2u];
  s.m3 = pieces[b + 3u];
  s.m4 = pieces[b + 4u];
  s.pixels = pieces[b + 5u].xy;
  return s;
}

void main() {
  uint k = kmeans_flat_invocation();
  if (k >= pc.clusters) return;
  uvec2 range = ranges[k];
  ClusterMoments sum = cluster_moments_zero();
  if (range.y > range.x) {
    uint first = range.x / pc.chunk + k;
    uint last = (range.y - 1u) / pc.chunk + k;
    sum = load_piece(first);
    for (uint p = first + 1u; p <= last; ++p) sum = cluster_moments_add(sum, load_piece(p));
  }
  vsgls[k] = cluster_vsgl(sum, range.y - range.x, centres[k], pc.space3d != 0u, pc.square_size);
}
