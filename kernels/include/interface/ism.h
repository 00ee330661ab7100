// The imperfect shadow maps' parameters, records and push constants (DESIGN.md §8a.2), shared by
// kernels/ism_*.comp, include/ism_lookup.glsl and harness/visibility/imperfect_shadow_maps.cpp
// through interop.h. Every map is a pyramid of uints in one storage buffer: level 0 (side x side
// texels) then each coarser level down to 1 x 1, row-major, map after map; a texel holds the
// float bits of the distance to the map's origin (positive floats order like their bits, so
// atomicMin keeps the nearest) or kIsmEmpty.
#ifndef VSGL_INTERFACE_ISM_H
#define VSGL_INTERFACE_ISM_H
#include "interop.h"

VSGL_INTERFACE_BEGIN

VSGL_CONST uint kIsmGroupSize = 64u;      // threads per group in x; y indexes the map (every ISM kernel)
VSGL_CONST uint kIsmEmpty = 0xFFFFFFFFu;  // no point landed in the texel (a NaN's bits: no depth)

// The defaults (DESIGN.md §8a.2): the paper's 64^2 maps; 8192 points per map, about 2 per texel of
// the square (1.3 in the hemisphere's disk where half the scene lies in front), so pull-push fills
// holes of a texel or two, not regions; a 3x3 PCF; a normal offset that keeps a planar receiver
// clear of its own depths over that footprint at any angle (> sqrt(2) (r + 1) texels); a depth
// bias of 1.5 % of the distance (a quarter to a half texel width at 64^2) as the margin for what
// the offset does not model: a receiver's curvature, the push's interpolation.
VSGL_CONST uint kIsmDefaultSide = 64u;
VSGL_CONST uint kIsmDefaultPointsPerMap = 8192u;
VSGL_CONST float kIsmDefaultDepthBias = 0.015f;
VSGL_CONST float kIsmDefaultNormalOffset = 3.0f;
VSGL_CONST uint kIsmDefaultPcfRadius = 1u;

// What every ISM kernel and the lookup read (the push constants of the splat).
struct IsmParams {
  uint side;  // texels per side of level 0 (a power of two)
  uint map_count;
  uint points_per_map;  // points each map splats
  uint map_stride;      // uints per map: side^2 + (side/2)^2 + ... + 1
  uint point_count;     // points in the shared array
  uint point_stride;    // map m splats points (m mod point_stride) + j point_stride, j < points_per_map
  float depth_bias;     // a tap occludes where its depth < (1 - depth_bias) x the receiver's distance
  float normal_offset;  // the receiver moves this many texel widths (at its distance) along its normal
  uint pcf_radius;      // (2 pcf_radius + 1)^2 taps
};
VSGL_LAYOUT(IsmParams, 36);

// A map's origin and the axis of its hemisphere: a VSGL's mean position and filtered normal
// (DESIGN.md §7). std430, 32 bytes.
struct IsmOrigin {
  vec4 position;  // xyz, 1
  vec4 normal;    // unit xyz, 0
};
VSGL_LAYOUT(IsmOrigin, 32);
VSGL_VEC4_AT(IsmOrigin, normal, 16);

// ism_pull.comp (fine level -> the next coarser) and ism_push.comp (coarser -> empty fine texels).
struct IsmPyramidPush {
  uint map_count;
  uint map_stride;
  uint fine_offset;    // uints from a map's start to the fine level
  uint fine_side;      // >= 2; the coarse level's side is half of it
  uint coarse_offset;  // ... and to the coarse level
};
VSGL_LAYOUT(IsmPyramidPush, 20);

// test_ism_lookup.comp: one visibility query of a map (a test's probe of ism_lookup.glsl).
struct IsmQuery {
  vec4 position;  // the receiver, xyz
  vec4 normal;    // its surface normal, xyz (either side; 0: no normal offset)
  uint map;
  uint reserved0;
  uint reserved1;
  uint reserved2;
};
VSGL_LAYOUT(IsmQuery, 48);
VSGL_VEC4_AT(IsmQuery, normal, 16);

struct IsmQueryPush {
  IsmParams params;
  uint count;
};
VSGL_LAYOUT(IsmQueryPush, 40);

VSGL_INTERFACE_END

#endif  // VSGL_INTERFACE_ISM_H
