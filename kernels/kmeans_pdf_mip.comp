#version 450
#extension GL_GOOGLE_include_directive : require
// k-means seeding: level l+1 of the PDF pyramid from level l, with the FIS mip pass's summation
// order (fis_mip_level.comp), so that the seeds are exactly the FIS kernel centres (DESIGN.md §5).
// The pyramid has a single layer holding q in .w; pyramid_total = 0 makes every layer index of
// pyramid.glsl address it.
#include "interface/kmeans.h"
layout(local_size_x_id = 0, local_size_y_id = 1) in;  // kKmeansImageGroupSize (interface/kmeans.h)
layout(std430, binding = 0) buffer Pyramid { vec4 pyramid_texels[]; };
#include "pyramid.glsl"

layout(push_constant) uniform PushBlock { KmeansMipPush pc; };

void main() {
  pyramid_init(pc.width, pc.height);
  pyramid_total = 0u;  // one layer
  uint dst = pc.source_level + 1u;
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= pyramid_level_width(dst) || p.y >= pyramid_level_height(dst)) return;
  ivec2 c = ivec2(p) * 2;
  precise float sum = pyramid_texel(0u, pc.source_level, c).w + pyramid_texel(0u, pc.source_level, c + ivec2(1, 0)).w;
  sum = sum + pyramid_texel(0u, pc.source_level, c + ivec2(0, 1)).w;
  sum = sum + pyramid_texel(0u, pc.source_level, c + ivec2(1, 1)).w;
  pyramid_texels[pyramid_offset[dst] + p.y * pyramid_level_width(dst) + p.x] = vec4(0.0, 0.0, 0.0, sum * 0.25);
}
