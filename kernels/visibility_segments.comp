#version 450
#extension GL_GOOGLE_include_directive : require
// Exact visibility of segments (DESIGN.md §8a.1): one thread per query (from, to, prepared by the
// host: interface/visibility.h's SegmentQuery), writing 1 where no triangle of the BVH crosses the
// segment more than the query's epsilon from its ends, else 0. The CPU twin is
// harness/visibility/bvh.cpp's segment_occluded, answer for answer. The host splits a long batch
// into dispatches of at most kVisibilityQueriesPerDispatch queries (ray_visibility.hpp).
// No shared memory; each thread's stack is kBvhMaxDepth uints of private memory.
#include "interface/visibility.h"

layout(local_size_x_id = 0) in;  // kVisibilityGroupSize

#define BVH_BINDING 0
#include "bvh_traverse.glsl"  // bindings 0 (nodes) and 1 (triangles)
layout(std430, binding = 2) readonly buffer Queries { SegmentQuery queries[]; };
layout(std430, binding = 3) writeonly buffer Visibility { uint visible[]; };
layout(push_constant) uniform PushBlock { VisibilityPush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.query_count) return;
  visible[i] = bvh_segment_occluded(queries[i], pc.node_count) ? 0u : 1u;
}
