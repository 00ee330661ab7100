#version 450
#extension GL_GOOGLE_include_directive : require
// k-means `sum`, segmented-reduction variant (kmeans_*_segsum, beyond the paper), step 1 of 2:
// the sorted order cut into chunks; thread j sums the moments of each cluster's texels inside
// chunk j and stores the piece of cluster k at slot j + k (as kmeans_update_pieces.comp does).
// The largest cluster then costs about CHUNK + size / CHUNK sequential steps instead of size.
#include "kmeans_common.glsl"
#include "vsgl_math.glsl"
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansNarrowGroupSize (interface/kmeans.h)
#include "view_layers.glsl"
layout(std430, binding = 1) readonly buffer Sorted { uvec2 sorted_pairs[]; };
layout(std430, binding = 2) writeonly buffer Pieces { vec4 pieces[]; };  // kKmeansPieceVec4s vec4 per slot
#define KMEANS_READS_VIEW
#include "kmeans_cluster.glsl"
#include "kmeans_sum_push.glsl"

void store_piece(uint slot, ClusterMoments s) {
  uint b = kKmeansPieceVec4s * slot;
  pieces[b] = s.m0;
  pieces[b + 1u] = s.m1;
  pieces[b + 2u] = s.m2;
  pieces[b + 3u] = s.m3;
  pieces[b + 4u] = s.m4;
  pieces[b + 5u] = vec4(s.pixels, 0.0, 0.0);
}

void main() {
  uint j = kmeans_flat_invocation();
  uint begin = j * pc.chunk;
  if (begin >= pc.texels) return;
  uint end = min(begin + pc.chunk, pc.texels);
  uint cluster = KMEANS_NO_CLUSTER;
  ClusterMoments sum = cluster_moments_zero();
  for (uint i = begin; i < end; ++i) {
    uvec2 pair = sorted_pairs[i];
    if (pair.x == KMEANS_NO_CLUSTER) break;
    ClusterMoments t = texel_cluster_moments(pair.y, pc.width, pc.height, pc.camera_view != 0u, pc.source_position.xyz);
    if (pair.x != cluster) {
      if (cluster != KMEANS_NO_CLUSTER) store_piece(j + cluster, sum);
      cluster = pair.x;
      sum = t;
    } else {
      sum = cluster_moments_add(sum, t);
    }
  }
  if (cluster != KMEANS_NO_CLUSTER) store_piece(j + cluster, sum);
}
