#version 450
#extension GL_GOOGLE_include_directive : require
// FIS "mipmapping" (`--mipmapping single-pass`, DESIGN.md §6.1a), part 2 of 2: one 16x16 group
// builds levels 7..L from the level-6 texels fis_mip_single_pass.comp left in `mid`, each texel
// mip_average() of its four children (missing children zero), writing in-bounds texels only.
#include "interface/fis.h"
#include "pyramid_layout.glsl"
#include "fis_spd_mid.glsl"
layout(local_size_x_id = 0, local_size_y_id = 1) in;

layout(std430, binding = 0) coherent buffer Mid { vec4 mid[]; };
// Levels 7..14 (entries above L repeat level L and are never written).
layout(binding = 1, rgba32f) uniform writeonly image2DArray levels[kFisSpdTailLevelSlots];
layout(push_constant) uniform PushBlock { FisMipPush pc; };

// Storage-image arrays may be indexed only by constants without an optional feature.
void store(uint level, ivec2 p, uint layer, vec4 v) {
  ivec3 q = ivec3(p, int(layer));
  switch (level) {
    case 7u: imageStore(levels[0], q, v); break;
    case 8u: imageStore(levels[1], q, v); break;
    case 9u: imageStore(levels[2], q, v); break;
    case 10u: imageStore(levels[3], q, v); break;
    case 11u: imageStore(levels[4], q, v); break;
    case 12u: imageStore(levels[5], q, v); break;
    case 13u: imageStore(levels[6], q, v); break;
    case 14u: imageStore(levels[7], q, v); break;
    default: break;
  }
}

vec4 mid_texel(uint layer, uint k, ivec2 c, uint stride) {
  if (uint(c.x) >= pyramid_level_width(k) || uint(c.y) >= pyramid_level_height(k)) return vec4(0.0);
  return mid[layer * stride + mid_offset(k) + uint(c.y) * pyramid_level_width(k) + uint(c.x)];
}

void main() {
  pyramid_init(pc.width, pc.height);
  uint t = gl_LocalInvocationIndex;
  uint threads = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
  uint stride = spd_mid_layer_texels();
  for (uint k = kFisSpdTileLevels + 1u; k <= pyramid_levels; ++k) {
    uint w = pyramid_level_width(k), h = pyramid_level_height(k);
    for (uint layer = 0u; layer < kMomentLayers; ++layer)
      for (uint idx = t; idx < w * h; idx += threads) {
        ivec2 p = ivec2(idx % w, idx / w);
        ivec2 c = p * 2;
        vec4 v = mip_average(mid_texel(layer, k - 1u, c, stride), mid_texel(layer, k - 1u, c + ivec2(1, 0), stride),
                             mid_texel(layer, k - 1u, c + ivec2(0, 1), stride),
                             mid_texel(layer, k - 1u, c + ivec2(1, 1), stride));
        mid[layer * stride + mid_offset(k) + idx] = v;
        store(k, p, layer, v);
      }
    memoryBarrierBuffer();
    barrier();
  }
}
