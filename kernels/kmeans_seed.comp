#version 450
#extension GL_GOOGLE_include_directive : require
// k-means seeding (DESIGN.md §6.2 "Seeds"): the N kernel centres of DESIGN.md §5 — the Fibonacci lattice
// warped down the PDF pyramid by hierarchical_warp.glsl — become the initial cluster centres:
// kmeans_2d: the kernel centre in pixels (x_i * S, inside the chosen texel); kmeans_3d: the world
// position of the chosen texel. One thread per cluster.
#include "kmeans_common.glsl"
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansNarrowGroupSize (interface/kmeans.h)
layout(std430, binding = 0) readonly buffer Pyramid { vec4 pyramid_texels[]; };
#include "pyramid.glsl"
#include "hierarchical_warp.glsl"
#define VIEW_BINDING 1
#include "view_layers.glsl"
layout(std430, binding = 2) writeonly buffer Centres { vec4 centres[]; };
layout(push_constant) uniform PushBlock { KmeansSeedPush pc; };

void main() {
  uint i = kmeans_flat_invocation();
  if (i >= pc.count) return;
  pyramid_init(pc.width, pc.height);
  pyramid_total = 0u;  // the single-layer PDF pyramid: PDF_LAYER addresses it too
  WarpedSample s = warp_sample(fibonacci_lattice(i, pc.count, pc.offset_bits));
  vec3 feature;
  if (pc.space3d != 0u)
    feature = view_position_valid(uint(s.texel.y) * pc.width + uint(s.texel.x)).xyz;
  else
    feature = vec3(s.x * float(pyramid_size), 0.0);
  centres[i] = vec4(feature, 0.0);
}
