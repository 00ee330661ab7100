// Exact visibility (DESIGN.md §8a.1): the BVH's node and triangle records, the segment query, and
// the push constants and work-group size of kernels/visibility_segments.comp, shared by the GLSL
// traversal (include/bvh_traverse.glsl) and the host (harness/visibility/). See interop.h for how
// C++ and GLSL share them; the records are std430 array elements, the same bytes on both sides.
#ifndef VSGL_INTERFACE_VISIBILITY_H
#define VSGL_INTERFACE_VISIBILITY_H
#include "interop.h"

VSGL_INTERFACE_BEGIN

VSGL_CONST uint kVisibilityGroupSize = 64u;  // threads per group, one segment query each

// The builder's guarantees: at most kBvhLeafSize triangles per leaf, at most kBvhMaxDepth nodes on
// any root-to-leaf path. The traversal keeps the second child of each interior node on its path in
// a stack of kBvhMaxDepth entries, of which it uses at most kBvhMaxDepth - 1.
VSGL_CONST uint kBvhLeafSize = 4u;
VSGL_CONST uint kBvhMaxDepth = 32u;

// The slab test widens each axis's parameter interval by 2^-20 of itself (the near end times
// kBvhSlabShrink or kBvhSlabGrow, whichever moves it toward -inf; the far end the other way), far
// above the few ulps by which the rounded interval can miss the exact one.
VSGL_CONST float kBvhSlabShrink = 0.99999904632568359375f;  // 1 - 2^-20, exact in float
VSGL_CONST float kBvhSlabGrow = 1.00000095367431640625f;    // 1 + 2^-20, exact in float

// One node, depth-first: an interior node's first child is the next node, its second child at
// `index`; a leaf holds triangles [index, index + count) of the BVH's triangle order.
struct BvhNode {
  float min_x;
  float min_y;
  float min_z;
  uint index;  // interior: the second child; leaf: the first triangle
  float max_x;
  float max_y;
  float max_z;
  uint count;  // leaf: 1..kBvhLeafSize triangles; 0: interior
};
VSGL_LAYOUT(BvhNode, 32);

// A triangle in the BVH's order: its three corners (xyz; w = 0).
struct BvhTriangle {
  vec4 v0;
  vec4 v1;
  vec4 v2;
};
VSGL_LAYOUT(BvhTriangle, 48);
VSGL_VEC4_AT(BvhTriangle, v0, 0);
VSGL_VEC4_AT(BvhTriangle, v2, 32);

// A segment from -> to, prepared once on the host (harness/visibility/segment_query.hpp) so that the
// kernel needs neither a division nor a square root: a hit counts where its parameter t (point =
// from + t (to - from)) lies strictly inside (t_min, t_max), t_min = epsilon / |to - from|,
// t_max = 1 - t_min.
struct SegmentQuery {
  vec4 origin_t_min;   // from, t_min
  vec4 delta_t_max;    // to - from, t_max
  vec4 inverse_delta;  // 1 / delta per axis; 0 where delta is 0 (w = 0)
};
VSGL_LAYOUT(SegmentQuery, 48);
VSGL_VEC4_AT(SegmentQuery, origin_t_min, 0);
VSGL_VEC4_AT(SegmentQuery, delta_t_max, 16);
VSGL_VEC4_AT(SegmentQuery, inverse_delta, 32);

// visibility_segments.comp
struct VisibilityPush {
  uint query_count;  // queries in this dispatch's buffer
  uint node_count;   // 0: an empty scene, everything visible
  uint reserved0;    // 0 (keeps the block 16 bytes)
  uint reserved1;
};
VSGL_LAYOUT(VisibilityPush, 16);

VSGL_INTERFACE_END

#endif  // VSGL_INTERFACE_VISIBILITY_H
