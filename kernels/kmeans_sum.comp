#version 450
#extension GL_GOOGLE_include_directive : require
// k-means `sum`, the paper-faithful variant (DESIGN.md §6.2, Prutkin et al.): one thread per cluster
// adds the moments of its texels one after another (cost linear in the largest cluster), then
// builds the cluster's VSGL (DESIGN.md §7).
#include "kmeans_common.glsl"
#include "vsgl_math.glsl"
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansNarrowGroupSize (interface/kmeans.h)
#include "view_layers.glsl"
layout(std430, binding = 1) readonly buffer Sorted { uvec2 sorted_pairs[]; };
layout(std430, binding = 2) readonly buffer Ranges { uvec2 ranges[]; };
layout(std430, binding = 3) readonly buffer Centres { vec4 centres[]; };
layout(std430, binding = 4) writeonly buffer Vsgls { Vsgl vsgls[]; };
#define KMEANS_READS_VIEW
#include "kmeans_cluster.glsl"
#include "kmeans_sum_push.glsl"

void main() {
  uint k = kmeans_flat_invocation();
  if (k >= pc.clusters) return;
  uvec2 range = ranges[k];
  ClusterMoments sum = cluster_moments_zero();
  for (uint i = range.x; i < range.y; ++i)
    sum = cluster_moments_add(sum, texel_cluster_moments(sorted_pairs[i].y, pc.width, pc.height, pc.camera_view != 0u,
                                                         pc.source_position.xyz));
  vsgls[k] = cluster_vsgl(sum, range.y - range.x, centres[k], pc.space3d != 0u, pc.square_size);
}
