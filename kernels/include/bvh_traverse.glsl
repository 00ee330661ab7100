#ifndef BVH_TRAVERSE_GLSL
#define BVH_TRAVERSE_GLSL
// Any-hit traversal of segments through the BVH (DESIGN.md §8a.1); CPU twins in
// harness/visibility/segment_query.cpp (the two tests) and bvh.cpp (the traversal), the same float
// operations in the same order. Every result is `precise` (no fused multiply-add), so the GPU
// answers as the CPU does, bit for bit: the tests use only +, -, * and comparisons, which Vulkan
// rounds correctly; the host prepared the query's divisions and square root (SegmentQuery).
// Binds the nodes at BVH_BINDING (default 0) and the triangles at BVH_BINDING + 1.
#include "interface/visibility.h"

#ifndef BVH_BINDING
#define BVH_BINDING 0
#endif
layout(std430, binding = BVH_BINDING) readonly buffer BvhNodes { BvhNode bvh_nodes[]; };
layout(std430, binding = BVH_BINDING + 1) readonly buffer BvhTriangles { BvhTriangle bvh_triangles[]; };

// Written out left to right (dot() and cross() leave the order to the driver).
float bvh_dot3(vec3 a, vec3 b) {
  precise float r = a.x * b.x + a.y * b.y + a.z * b.z;
  return r;
}
vec3 bvh_cross3(vec3 a, vec3 b) {
  precise vec3 r = vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  return r;
}

// The slab test for parameters in [0, 1], each axis's interval widened by 2^-20 of itself; an axis
// the segment does not move along is a containment test. Monotone in the box.
bool bvh_segment_overlaps_box(SegmentQuery q, vec3 lo, vec3 hi) {
  float t_lo = 0.0;
  float t_hi = 1.0;
  for (int a = 0; a < 3; ++a) {
    float o = q.origin_t_min[a];
    float inverse = q.inverse_delta[a];
    if (inverse == 0.0) {
      if (o < lo[a] || o > hi[a]) return false;
      continue;
    }
    precise float t0 = (lo[a] - o) * inverse;
    precise float t1 = (hi[a] - o) * inverse;
    float near_t = min(t0, t1);
    float far_t = max(t0, t1);
    precise float near_wide = near_t * (near_t > 0.0 ? kBvhSlabShrink : kBvhSlabGrow);
    precise float far_wide = far_t * (far_t > 0.0 ? kBvhSlabGrow : kBvhSlabShrink);
    t_lo = max(t_lo, near_wide);
    t_hi = min(t_hi, far_wide);
  }
  return t_lo <= t_hi;
}

// The triangle's own box, then Moeller-Trumbore without its division: u, v, t scaled by det.
bool bvh_segment_hits_triangle(SegmentQuery q, vec3 v0, vec3 v1, vec3 v2) {
  if (!bvh_segment_overlaps_box(q, min(min(v0, v1), v2), max(max(v0, v1), v2))) return false;
  precise vec3 e1 = v1 - v0;
  precise vec3 e2 = v2 - v0;
  vec3 p = bvh_cross3(q.delta_t_max.xyz, e2);
  float det = bvh_dot3(e1, p);
  if (det == 0.0) return false;
  precise vec3 s = q.origin_t_min.xyz - v0;
  float u = bvh_dot3(s, p);
  vec3 r = bvh_cross3(s, e1);
  float v = bvh_dot3(q.delta_t_max.xyz, r);
  float t = bvh_dot3(e2, r);
  if (det < 0.0) {
    det = -det;
    u = -u;
    v = -v;
    t = -t;
  }
  precise float uv = u + v;
  precise float t_from = q.origin_t_min.w * det;
  precise float t_to = q.delta_t_max.w * det;
  return u >= 0.0 && v >= 0.0 && uv <= det && t > t_from && t < t_to;
}

// Any triangle occludes the segment. Depth first, the second child of each interior node on the
// path on a stack: the builder keeps paths to kBvhMaxDepth nodes, so it holds at most
// kBvhMaxDepth - 1 entries (the host refuses a deeper tree; were one bound anyway, the overflow
// answers "occluded" rather than write past the stack).
bool bvh_segment_occluded(SegmentQuery q, uint node_count) {
  if (node_count == 0u) return false;
  uint stack[kBvhMaxDepth];
  uint size = 0u;
  uint node = 0u;
  for (;;) {
    BvhNode n = bvh_nodes[node];
    if (bvh_segment_overlaps_box(q, vec3(n.min_x, n.min_y, n.min_z), vec3(n.max_x, n.max_y, n.max_z))) {
      if (n.count == 0u) {
        if (size == kBvhMaxDepth) return true;
        stack[size] = n.index;
        ++size;
        node = node + 1u;
        continue;
      }
      for (uint k = n.index; k < n.index + n.count; ++k) {
        BvhTriangle tri = bvh_triangles[k];
        if (bvh_segment_hits_triangle(q, tri.v0.xyz, tri.v1.xyz, tri.v2.xyz)) return true;
      }
    }
    if (size == 0u) return false;
    --size;
    node = stack[size];
  }
  return false;
}

#endif
