#version 450
#extension GL_GOOGLE_include_directive : require
// FIS "mipmapping" on the sampled-image pyramid, one dispatch per level (`--mipmapping per-level`):
// level l+1 of the three array layers from level l, as fis_mip_level.comp does on the buffer
// (same mip_average, so bit-exact with the CPU reference). Only in-bounds texels are read or
// written; the padding of the virtual square stays the zero it was cleared to.
#include "interface/fis.h"
#include "pyramid_layout.glsl"
layout(local_size_x_id = 0, local_size_y_id = 1) in;
layout(binding = 0, rgba32f) uniform readonly image2DArray source;
layout(binding = 1, rgba32f) uniform writeonly image2DArray destination;
layout(push_constant) uniform PushBlock { FisMipPush pc; };

vec4 child(uint layer, ivec2 c) {
  uint l = pc.source_level;
  if (uint(c.x) >= pyramid_level_width(l) || uint(c.y) >= pyramid_level_height(l)) return vec4(0.0);
  return imageLoad(source, ivec3(c, int(layer)));
}

void main() {
  pyramid_init(pc.width, pc.height);
  uint dst = pc.source_level + 1u;
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= pyramid_level_width(dst) || p.y >= pyramid_level_height(dst)) return;
  ivec2 c = ivec2(p) * 2;
  for (uint layer = 0u; layer < kMomentLayers; ++layer)
    imageStore(destination, ivec3(p, int(layer)),
               mip_average(child(layer, c), child(layer, c + ivec2(1, 0)), child(layer, c + ivec2(0, 1)),
                           child(layer, c + ivec2(1, 1))));
}
