#version 450
#extension GL_GOOGLE_include_directive : require
// k-means centre update, step 2 of 2: one thread per cluster adds its pieces in chunk order and
// moves the centre to the q-weighted mean of its features. A cluster with no texel, or whose
// texels all have q = 0, keeps its centre (DESIGN.md §6.2).
#include "kmeans_common.glsl"
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansNarrowGroupSize (interface/kmeans.h)
layout(std430, binding = 0) readonly buffer Ranges { uvec2 ranges[]; };
layout(std430, binding = 1) readonly buffer Pieces { vec4 pieces[]; };
layout(std430, binding = 2) buffer Centres { vec4 centres[]; };
layout(push_constant) uniform PushBlock { KmeansUpdatePush pc; };

void main() {
  uint k = kmeans_flat_invocation();
  if (k >= pc.clusters) return;
  uvec2 range = ranges[k];
  if (range.x == range.y) return;
  uint first = range.x / pc.chunk + k;
  uint last = (range.y - 1u) / pc.chunk + k;
  precise vec4 sum = pieces[first];
  for (uint p = first + 1u; p <= last; ++p) sum = sum + pieces[p];
  if (!(sum.w > 0.0)) return;
  precise vec3 mean = vec3(sum.x / sum.w, sum.y / sum.w, sum.z / sum.w);
  centres[k] = vec4(mean, 0.0);
}
