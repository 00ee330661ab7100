#pragma once
// A segment query and the two tests a traversal makes with it (DESIGN.md §8a.1), the CPU twins of
// kernels/include/bvh_traverse.glsl: the same float operations in the same order, no fused
// multiply-add (harness/CMakeLists.txt builds segment_query.cpp with -ffp-contract=off, the kernel
// marks its arithmetic `precise`), so the CPU and the GPU answer every query alike, bit for bit.
#include <glm/glm.hpp>

#include "kernels/include/interface/visibility.h"

namespace vsgl {

// The query for the segment from -> to: a triangle occludes it where the segment crosses it more
// than `epsilon` (world units) from either end, so a light or a receiver lying on a surface does
// not shadow itself. A segment no longer than 2 epsilon (or of length 0) is never occluded. A delta
// component below FLT_MIN in magnitude is taken as 0 (its inverse would overflow). Throws
// InputError for an epsilon that is negative or not finite, or an end that is not finite.
gpu::SegmentQuery make_segment_query(glm::vec3 from, glm::vec3 to, float epsilon);

// Whether the segment's line, for parameters in [0, 1], meets the box [lo, hi]: the slab test with
// each axis's interval widened by 2^-20 of itself (kBvhSlabShrink, kBvhSlabGrow). Monotone in the
// box: a box inside another never passes where the outer one fails, so a traversal that skips a
// failing node skips nothing a leaf would have accepted.
bool segment_overlaps_box(const gpu::SegmentQuery& q, glm::vec3 lo, glm::vec3 hi);

// Whether the triangle (v0, v1, v2) occludes the segment: its own box passes segment_overlaps_box,
// and the Moeller-Trumbore test, without its division (u, v and t stay scaled by the determinant),
// finds the crossing inside the triangle (edges included) at t_min < t < t_max. A triangle parallel
// to the segment or of zero area (determinant 0) never occludes.
bool segment_hits_triangle(const gpu::SegmentQuery& q, glm::vec3 v0, glm::vec3 v1, glm::vec3 v2);

}  // namespace vsgl
