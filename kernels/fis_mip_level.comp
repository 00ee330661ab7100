#version 450
#extension GL_GOOGLE_include_directive : require
// FIS phase 2, "mipmapping", on the storage-buffer pyramid: level l+1 of every moment layer from
// level l (DESIGN.md §4), the mean of the four children, missing children counting as zero, summed in
// a fixed order (mip_average) so the CPU reference can match it bit for bit. One dispatch per
// level, one thread per output texel.
#include "interface/fis.h"
layout(local_size_x_id = 0, local_size_y_id = 1) in;
layout(std430, binding = 0) buffer Pyramid { vec4 pyramid_texels[]; };
#include "pyramid.glsl"
layout(push_constant) uniform PushBlock { FisMipPush pc; };

void main() {
  pyramid_init(pc.width, pc.height);
  uint dst = pc.source_level + 1u;
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= pyramid_level_width(dst) || p.y >= pyramid_level_height(dst)) return;
  ivec2 c = ivec2(p) * 2;
  uint out_index = pyramid_offset[dst] + p.y * pyramid_level_width(dst) + p.x;
  for (uint layer = 0u; layer < kMomentLayers; ++layer) {
    pyramid_texels[layer * pyramid_total + out_index] =
        mip_average(pyramid_texel(layer, pc.source_level, c), pyramid_texel(layer, pc.source_level, c + ivec2(1, 0)),
                    pyramid_texel(layer, pc.source_level, c + ivec2(0, 1)),
                    pyramid_texel(layer, pc.source_level, c + ivec2(1, 1)));
  }
}
