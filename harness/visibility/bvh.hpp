#pragma once
// A bounding volume hierarchy over a triangle soup, built on the CPU with binned SAH and flattened
// into the node array the GPU traverses as it is (DESIGN.md §8a.1; records in
// kernels/include/interface/visibility.h), and the CPU any-hit traversal of segments through it.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "harness/visibility/triangle_soup.hpp"
#include "kernels/include/interface/visibility.h"

namespace vsgl {

inline constexpr uint32_t kBvhBins = 16;  // SAH bins per axis, over the node's centroid bounds

struct BvhBuildOptions {
  // Nodes on any root-to-leaf path, at most gpu::kBvhMaxDepth (the traversal's stack). A split
  // whose larger side could not be finished within what is left by halving is replaced by a median
  // split, so every soup of n triangles gets a tree within the bound as long as
  // bvh_median_levels(n) <= max_depth.
  uint32_t max_depth = gpu::kBvhMaxDepth;
};

struct Bvh {
  std::vector<gpu::BvhNode> nodes;       // depth-first, the root first; empty for an empty soup
  std::vector<uint32_t> triangle_order;  // position in the leaves' order -> triangle of the soup
  uint32_t depth = 0;                    // nodes on the longest root-to-leaf path
  std::string soup_hash;                 // soup_content_hash of the soup it was built over
};

// Levels a tree of n triangles needs when every split halves (the larger half ceil(n / 2)) and
// leaves hold kBvhLeafSize: 1 for n <= kBvhLeafSize, else 1 + bvh_median_levels(ceil(n / 2)).
uint32_t bvh_median_levels(uint64_t n);

// Deterministic: the same soup gives the same node array, bit for bit (no threads, no unordered
// containers, every tie broken by axis, then bin, then triangle index). Throws InputError for an
// invalid soup (require_valid_soup), one of more than 2^31 triangles (node indices are 32-bit),
// a max_depth above gpu::kBvhMaxDepth, or one below bvh_median_levels(n), naming both.
Bvh build_bvh(const TriangleSoup& soup, const BvhBuildOptions& options = {});

// The soup's triangles in the BVH's order, as the GPU reads them.
std::vector<gpu::BvhTriangle> bvh_triangles(const Bvh& bvh, const TriangleSoup& soup);

// Any-hit: whether a triangle of the soup occludes the segment (segment_query.hpp's rule: crossings
// within `epsilon` of either end do not count). `bvh` must have been built over `soup` (its
// triangle count is checked: InputError).
bool segment_occluded(const Bvh& bvh, const TriangleSoup& soup, glm::vec3 from, glm::vec3 to, float epsilon);
bool segment_occluded(const Bvh& bvh, const TriangleSoup& soup, const gpu::SegmentQuery& query);

// The same answer from every triangle in turn, without the BVH: the twin the tests compare with.
bool segment_occluded_brute_force(const TriangleSoup& soup, glm::vec3 from, glm::vec3 to, float epsilon);

}  // namespace vsgl
