// The BVH and its CPU traversal (DESIGN.md §8a.1): the traversal answers every segment as the brute
// force over all triangles does, the epsilon rule keeps a point on a surface from shadowing itself,
// the node array is deterministic and well formed, and the depth bound holds where SAH alone would
// build a chain. No device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "harness/core/error.hpp"
#include "harness/visibility/bvh.hpp"
#include "harness/visibility/segment_query.hpp"
#include "harness/visibility/triangle_soup.hpp"
#include "input_error.hpp"
#include "visibility_soups.hpp"

namespace vsgl {
namespace {

// Every triangle in exactly one leaf, leaves of 1..kBvhLeafSize, children inside their parent's
// box, every triangle inside its leaf's box, the first child next, the depth as recorded.
void expect_well_formed_bvh(const Bvh& bvh, const TriangleSoup& soup) {
  ASSERT_EQ(bvh.triangle_order.size(), soup.triangle_count());
  std::vector<uint32_t> sorted = bvh.triangle_order;
  std::sort(sorted.begin(), sorted.end());
  for (uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i) << "the order is not a permutation";
  if (soup.triangle_count() == 0) {
    EXPECT_TRUE(bvh.nodes.empty());
    return;
  }
  const auto inside = [](const gpu::BvhNode& in, const gpu::BvhNode& out) {
    return in.min_x >= out.min_x && in.min_y >= out.min_y && in.min_z >= out.min_z && in.max_x <= out.max_x &&
           in.max_y <= out.max_y && in.max_z <= out.max_z;
  };
  std::vector<uint32_t> covered(soup.triangle_count(), 0);
  uint32_t depth = 0;
  struct Visit {
    uint32_t node, level;
  };
  std::vector<Visit> todo = {{0, 1}};
  std::size_t visited = 0;
  while (!todo.empty()) {
    const Visit v = todo.back();
    todo.pop_back();
    ++visited;
    ASSERT_LT(v.node, bvh.nodes.size());
    const gpu::BvhNode& n = bvh.nodes[v.node];
    depth = std::max(depth, v.level);
    if (n.count > 0) {
      ASSERT_LE(n.count, gpu::kBvhLeafSize);
      for (uint32_t k = n.index; k < n.index + n.count; ++k) {
        ASSERT_LT(k, covered.size());
        ++covered[k];
        const std::size_t t = bvh.triangle_order[k];
        for (int c = 0; c < 3; ++c) {
          const glm::vec3 p = soup.vertices[3 * t + c];
          ASSERT_TRUE(p.x >= n.min_x && p.y >= n.min_y && p.z >= n.min_z && p.x <= n.max_x && p.y <= n.max_y &&
                      p.z <= n.max_z)
              << "triangle " << t << " sticks out of its leaf " << v.node;
        }
      }
      continue;
    }
    ASSERT_GT(n.index, v.node + 1);
    ASSERT_LT(n.index, bvh.nodes.size());
    EXPECT_TRUE(inside(bvh.nodes[v.node + 1], n) && inside(bvh.nodes[n.index], n)) << "node " << v.node;
    todo.push_back({v.node + 1, v.level + 1});
    todo.push_back({n.index, v.level + 1});
  }
  EXPECT_EQ(visited, bvh.nodes.size()) << "nodes no path reaches";
  for (std::size_t k = 0; k < covered.size(); ++k) ASSERT_EQ(covered[k], 1u) << "leaf position " << k;
  EXPECT_EQ(depth, bvh.depth);
  EXPECT_LE(bvh.depth, gpu::kBvhMaxDepth);
}

TEST(VisibilityBvh, AgreesWithTheBruteForceOnRandomSoups) {
  uint64_t occluded = 0, visible = 0, grazing_occluded = 0, compared = 0;
  for (const uint32_t seed : {1u, 2u, 3u}) {
    for (const uint32_t size : {1u, 2u, 3u, 5u, 17u, 100u, 500u, 2000u}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(size) + " triangles");
      const TriangleSoup soup = test::random_soup(seed, size);
      const Bvh bvh = build_bvh(soup);
      expect_well_formed_bvh(bvh, soup);
      const auto segments = test::random_segments(soup, seed + 100, size >= 500 ? 1200 : 600);
      uint32_t mismatches = 0;
      for (std::size_t i = 0; i < segments.size(); ++i) {
        const test::TestSegment& s = segments[i];
        const bool fast = segment_occluded(bvh, soup, s.from, s.to, s.epsilon);
        const bool slow = segment_occluded_brute_force(soup, s.from, s.to, s.epsilon);
        if (fast != slow && ++mismatches <= 5)
          ADD_FAILURE() << "segment " << i << " (kind " << i % 6 << "): BVH " << fast << ", brute force " << slow;
        ++compared;
        (slow ? occluded : visible) += 1;
        if (slow && (i % 6 == 1 || i % 6 == 2)) ++grazing_occluded;
      }
      EXPECT_EQ(mismatches, 0u);
    }
  }
  // Both answers, and hits through edges and vertices, are common: the comparison is not vacuous.
  EXPECT_GT(occluded, compared / 10) << occluded << " of " << compared;
  EXPECT_GT(visible, compared / 10) << visible << " of " << compared;
  EXPECT_GT(grazing_occluded, compared / 50) << grazing_occluded << " of " << compared;
}

// A triangle in the plane z = 0 around the origin.
TriangleSoup one_occluder(glm::vec3 offset = glm::vec3(0.0f)) {
  TriangleSoup soup;
  soup.vertices = {glm::vec3(-1.0f, -1.0f, 0.0f) + offset, glm::vec3(2.0f, -1.0f, 0.0f) + offset,
                   glm::vec3(-1.0f, 2.0f, 0.0f) + offset};
  return soup;
}

bool occluded_both_ways(const TriangleSoup& soup, glm::vec3 from, glm::vec3 to, float epsilon) {
  const bool fast = segment_occluded(build_bvh(soup), soup, from, to, epsilon);
  EXPECT_EQ(fast, segment_occluded_brute_force(soup, from, to, epsilon));
  return fast;
}

TEST(VisibilityBvh, OneOccluderBetweenTwoPoints) {
  const glm::vec3 below(0.1f, 0.2f, -1.0f), above(0.1f, 0.2f, 1.0f);
  EXPECT_TRUE(occluded_both_ways(one_occluder(), below, above, 1e-4f));
  EXPECT_TRUE(occluded_both_ways(one_occluder(), above, below, 1e-4f)) << "the direction matters";
  EXPECT_FALSE(occluded_both_ways(TriangleSoup{}, below, above, 1e-4f)) << "removed";
  EXPECT_FALSE(occluded_both_ways(one_occluder(glm::vec3(5.0f, 0.0f, 0.0f)), below, above, 1e-4f)) << "moved aside";
  EXPECT_FALSE(occluded_both_ways(one_occluder(glm::vec3(0.0f, 0.0f, 2.0f)), below, above, 1e-4f))
      << "moved past the end";
  EXPECT_FALSE(occluded_both_ways(one_occluder(), below, glm::vec3(0.1f, 0.2f, -0.5f), 0.0f)) << "stops short";
  // A segment beside the triangle, grazing past its slanted edge x + y = 1 at distance 0.01.
  EXPECT_FALSE(occluded_both_ways(one_occluder(), glm::vec3(0.51f, 0.51f, -1.0f), glm::vec3(0.51f, 0.51f, 1.0f), 0.0f));
  EXPECT_TRUE(occluded_both_ways(one_occluder(), glm::vec3(0.49f, 0.49f, -1.0f), glm::vec3(0.49f, 0.49f, 1.0f), 0.0f));
  // A degenerate triangle (corners on a line) never occludes.
  TriangleSoup line;
  line.vertices = {glm::vec3(-1.0f, 0.2f, 0.0f), glm::vec3(0.0f, 0.2f, 0.0f), glm::vec3(1.0f, 0.2f, 0.0f)};
  EXPECT_FALSE(occluded_both_ways(line, below, above, 0.0f));
}

TEST(VisibilityBvh, EpsilonKeepsAPointOnASurfaceFromShadowingItself) {
  const TriangleSoup soup = one_occluder();
  const glm::vec3 on_surface(0.1f, 0.2f, 0.0f), light(0.3f, -0.1f, 1.0f);
  EXPECT_FALSE(occluded_both_ways(soup, on_surface, light, 1e-4f));
  EXPECT_FALSE(occluded_both_ways(soup, light, on_surface, 1e-4f)) << "at the far end too";
  // 1e-3 below the surface: the crossing is within an epsilon of 1e-2 of the end, not of 1e-4.
  const glm::vec3 just_below(0.1f, 0.2f, -1e-3f);
  EXPECT_FALSE(occluded_both_ways(soup, just_below, light, 1e-2f));
  EXPECT_TRUE(occluded_both_ways(soup, just_below, light, 1e-4f));
  EXPECT_FALSE(occluded_both_ways(soup, light, just_below, 1e-2f));
  EXPECT_TRUE(occluded_both_ways(soup, light, just_below, 1e-4f));
  // The epsilon spares only the ends: an occluder in the middle still counts.
  EXPECT_TRUE(occluded_both_ways(one_occluder(glm::vec3(0.0f, 0.0f, 0.5f)), on_surface, light, 1e-2f));
  // A segment no longer than 2 epsilon is never occluded.
  EXPECT_FALSE(occluded_both_ways(soup, glm::vec3(0.1f, 0.2f, -0.01f), glm::vec3(0.1f, 0.2f, 0.01f), 0.011f));
  EXPECT_TRUE(occluded_both_ways(soup, glm::vec3(0.1f, 0.2f, -0.01f), glm::vec3(0.1f, 0.2f, 0.01f), 0.009f));
  EXPECT_NE(test::input_error([] { make_segment_query(glm::vec3(0.0f), glm::vec3(1.0f), -1e-3f); }).find("epsilon"),
            std::string::npos);
}

TEST(VisibilityBvh, TheSameSoupGivesTheSameNodeArray) {
  const TriangleSoup soup = test::random_soup(7, 2000);
  const TriangleSoup copy = soup;
  const Bvh a = build_bvh(soup);
  const Bvh b = build_bvh(copy);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  ASSERT_GT(a.nodes.size(), 2000u / gpu::kBvhLeafSize);
  EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(gpu::BvhNode)), 0);
  EXPECT_EQ(a.triangle_order, b.triangle_order);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.soup_hash, soup_content_hash(soup));
  EXPECT_EQ(a.soup_hash.rfind("fnv1a64:", 0), 0u);
  EXPECT_EQ(a.soup_hash.size(), 8u + 16u);
  TriangleSoup moved = soup;
  moved.vertices[1234].y += 1e-3f;
  EXPECT_NE(soup_content_hash(moved), a.soup_hash);
}

TEST(VisibilityBvh, SoupHashIsFnv1aOverTheFloatBytes) {
  // FNV-1a 64 of no bytes is its offset basis; of the 12 bytes of (0, 0, 0) it is fixed too.
  EXPECT_EQ(soup_content_hash(TriangleSoup{}), "fnv1a64:cbf29ce484222325");
  TriangleSoup zeros;
  zeros.vertices = {glm::vec3(0.0f)};
  uint64_t h = 14695981039346656037ull;
  for (int i = 0; i < 12; ++i) h = (h ^ 0u) * 1099511628211ull;
  char expected[32];
  std::snprintf(expected, sizeof expected, "fnv1a64:%016llx", static_cast<unsigned long long>(h));
  EXPECT_EQ(soup_content_hash(zeros), expected);
}

// Small triangles in the plane z = 0 at x = 1.3^k, each 1e-4 x long: binned SAH splits off the few
// farthest at every node, a chain about n / 10 deep. The bound caps it, and the capped trees still
// find every triangle.
TEST(VisibilityBvh, DepthBoundHoldsWhereSahWouldBuildAChain) {
  constexpr int kCount = 300;
  TriangleSoup chain;
  for (int k = 0; k < kCount; ++k) {
    const float x = std::pow(1.3f, static_cast<float>(k));
    chain.vertices.insert(chain.vertices.end(), {glm::vec3(x, -0.01f, 0.0f), glm::vec3(x * 1.0001f, -0.01f, 0.0f),
                                                 glm::vec3(x, 0.01f, 0.0f)});
  }
  const uint32_t least = bvh_median_levels(kCount);
  EXPECT_EQ(least, 8u);  // 300 -> 150 -> 75 -> 38 -> 19 -> 10 -> 5 -> 3
  const Bvh free = build_bvh(chain);
  expect_well_formed_bvh(free, chain);
  EXPECT_GT(free.depth, least + 4) << "the soup does not make SAH chain: the bound below would be untested";
  for (uint32_t bound = least; bound <= free.depth; ++bound) {
    SCOPED_TRACE("max_depth " + std::to_string(bound));
    const Bvh capped = build_bvh(chain, BvhBuildOptions{bound});
    expect_well_formed_bvh(capped, chain);
    EXPECT_LE(capped.depth, bound);
    if (bound < free.depth) {
      EXPECT_EQ(capped.depth, bound) << "the cap did not bind";
    }
    for (int k = 0; k < kCount; k += 7) {
      const float x = std::pow(1.3f, static_cast<float>(k)) * 1.00002f;
      const glm::vec3 from(x, 0.0f, -1.0f), to(x, 0.0f, 1.0f), beside(x, 0.05f, 1.0f);
      EXPECT_TRUE(segment_occluded(capped, chain, from, to, 0.0f)) << k;
      EXPECT_FALSE(segment_occluded(capped, chain, from, beside, 0.0f)) << k;
    }
  }
  const std::string below = test::input_error([&] { build_bvh(chain, BvhBuildOptions{least - 1}); });
  EXPECT_NE(below.find("need at least 8 levels"), std::string::npos) << below;
  const std::string above = test::input_error([&] { build_bvh(chain, BvhBuildOptions{gpu::kBvhMaxDepth + 1}); });
  EXPECT_NE(above.find("kBvhMaxDepth"), std::string::npos) << above;
}

TEST(VisibilityBvh, IdenticalTrianglesAreHalvedAtTheMedian) {
  TriangleSoup same;
  for (int k = 0; k < 1000; ++k)
    same.vertices.insert(same.vertices.end(),
                         {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)});
  const Bvh bvh = build_bvh(same);
  expect_well_formed_bvh(bvh, same);
  EXPECT_EQ(bvh.depth, bvh_median_levels(1000));
  EXPECT_TRUE(segment_occluded(bvh, same, glm::vec3(0.2f, 0.2f, -1.0f), glm::vec3(0.2f, 0.2f, 1.0f), 0.0f));
}

TEST(VisibilityBvh, RefusesAnInvalidSoupOrAForeignOne) {
  TriangleSoup partial;
  partial.vertices = {glm::vec3(0.0f), glm::vec3(1.0f)};
  EXPECT_NE(test::input_error([&] { build_bvh(partial); }).find("not a whole number of triangles"), std::string::npos);
  TriangleSoup nan = one_occluder();
  nan.vertices[2].z = std::nanf("");
  EXPECT_NE(test::input_error([&] { build_bvh(nan); }).find("not finite"), std::string::npos);
  const Bvh bvh = build_bvh(one_occluder());
  EXPECT_NE(test::input_error([&] {
              segment_occluded(bvh, test::random_soup(1, 3), glm::vec3(0.0f), glm::vec3(1.0f), 0.0f);
            }).find("used with a soup of 3"),
            std::string::npos);
}

}  // namespace
}  // namespace vsgl
