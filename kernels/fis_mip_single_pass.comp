#version 450
#extension GL_GOOGLE_include_directive : require
// FIS "mipmapping" on the sampled-image pyramid (`--mipmapping single-pass`, DESIGN.md §6.1a), in
// the manner of AMD FidelityFX SPD, part 1 of 2: each 16x16 group reduces a 64x64 tile of level 0
// to levels 1..6 (level 1-2 in registers, 3-6 in shared memory), writing every in-bounds texel of
// those levels and its level-6 texel to a buffer; fis_mip_single_pass_tail.comp (one group, the
// next dispatch) builds levels 7..L from that buffer. Two dispatches instead of one with a
// last-group atomic hand-over keep each within 8 storage images per stage (7 here, 8 there; the
// desktop baseline's maxPerStageDescriptorStorageImages, see harness/vk/portability_baselines.cpp)
// with the same arithmetic. Every texel is mip_average() of its four children, so the chain is
// bit-exact with the CPU reference; texels outside a level's in-bounds extent are neither read
// nor written (the padding stays zero).
#include "interface/fis.h"
#include "pyramid_layout.glsl"
#include "fis_spd_mid.glsl"
layout(local_size_x_id = 0, local_size_y_id = 1) in;

// Level-6 (and coarser) texels of the kMomentLayers layers, level after level (in-bounds extents only).
layout(std430, binding = 0) writeonly buffer Mid { vec4 mid[]; };
layout(binding = 1, rgba32f) uniform readonly image2DArray level0;
// Levels 1..6 (entries above L repeat level L and are never written).
layout(binding = 2, rgba32f) uniform writeonly image2DArray levels[kFisSpdTileLevels];
layout(push_constant) uniform PushBlock { FisMipPush pc; };

const uint TILE_LEVELS = kFisSpdTileLevels;  // 64 = 2^6 texels per tile side
shared vec4 s_a[256];
shared vec4 s_b[64];

// Storage-image arrays may be indexed only by constants without an optional feature.
void store(uint level, ivec2 p, uint layer, vec4 v) {
  if (level > pyramid_levels || uint(p.x) >= pyramid_level_width(level) || uint(p.y) >= pyramid_level_height(level))
    return;
  ivec3 q = ivec3(p, int(layer));
  switch (level) {
    case 1u: imageStore(levels[0], q, v); break;
    case 2u: imageStore(levels[1], q, v); break;
    case 3u: imageStore(levels[2], q, v); break;
    case 4u: imageStore(levels[3], q, v); break;
    case 5u: imageStore(levels[4], q, v); break;
    case 6u: imageStore(levels[5], q, v); break;
    default: break;
  }
}

vec4 load0(ivec2 p, uint layer) {
  if (uint(p.x) >= pc.width || uint(p.y) >= pc.height) return vec4(0.0);
  return imageLoad(level0, ivec3(p, int(layer)));
}

// Four entries of a square shared array of side `side`, children of (x, y).
#define CHILDREN(arr, side, x, y) \
  arr[(2u * (y)) * (side) + 2u * (x)], arr[(2u * (y)) * (side) + 2u * (x) + 1u], \
  arr[(2u * (y) + 1u) * (side) + 2u * (x)], arr[(2u * (y) + 1u) * (side) + 2u * (x) + 1u]

void main() {
  pyramid_init(pc.width, pc.height);
  uint t = gl_LocalInvocationIndex;
  uvec2 tl = gl_LocalInvocationID.xy;
  uvec2 g = gl_WorkGroupID.xy;
  uint stride = spd_mid_layer_texels();  // one layer's part of `mid`

  for (uint layer = 0u; layer < kMomentLayers; ++layer) {
    // Levels 1 and 2 in registers: this thread's 4x4 texels of level 0.
    ivec2 b0 = ivec2(g * 64u + tl * 4u);
    vec4 l1[4];
    for (uint j = 0u; j < 2u; ++j)
      for (uint i = 0u; i < 2u; ++i) {
        ivec2 c = b0 + ivec2(2u * i, 2u * j);
        vec4 v = mip_average(load0(c, layer), load0(c + ivec2(1, 0), layer), load0(c + ivec2(0, 1), layer),
                             load0(c + ivec2(1, 1), layer));
        l1[j * 2u + i] = v;
        store(1u, ivec2(g * 32u + tl * 2u) + ivec2(i, j), layer, v);
      }
    vec4 v2 = mip_average(l1[0], l1[1], l1[2], l1[3]);
    store(2u, ivec2(g * 16u + tl), layer, v2);
    s_a[t] = v2;
    barrier();
    // Levels 3..6 in shared memory (8x8, 4x4, 2x2, 1x1 per tile).
    if (t < 64u) {
      uint x = t % 8u, y = t / 8u;
      vec4 v = mip_average(CHILDREN(s_a, 16u, x, y));
      s_b[t] = v;
      store(3u, ivec2(g * 8u + uvec2(x, y)), layer, v);
    }
    barrier();
    if (t < 16u) {
      uint x = t % 4u, y = t / 4u;
      vec4 v = mip_average(CHILDREN(s_b, 8u, x, y));
      s_a[t] = v;
      store(4u, ivec2(g * 4u + uvec2(x, y)), layer, v);
    }
    barrier();
    if (t < 4u) {
      uint x = t % 2u, y = t / 2u;
      vec4 v = mip_average(CHILDREN(s_a, 4u, x, y));
      s_b[t] = v;
      store(5u, ivec2(g * 2u + uvec2(x, y)), layer, v);
    }
    barrier();
    if (t == 0u) {
      vec4 v = mip_average(s_b[0], s_b[1], s_b[2], s_b[3]);
      store(6u, ivec2(g), layer, v);
      if (pyramid_levels > TILE_LEVELS) mid[layer * stride + g.y * pyramid_level_width(TILE_LEVELS) + g.x] = v;
    }
    barrier();
  }
}
