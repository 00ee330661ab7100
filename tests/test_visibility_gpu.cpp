// Exact visibility on the GPU (DESIGN.md §8a.1): kernels/visibility_segments.comp answers every
// segment query as the CPU traversal does, bit for bit, in one dispatch or many; one occluder gives
// 0 and 1; a BVH beyond the device's maxStorageBufferRange is refused before anything is created.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "gpu_test.hpp"
#include "harness/core/error.hpp"
#include "harness/visibility/bvh.hpp"
#include "harness/visibility/ray_visibility.hpp"
#include "harness/visibility/segment_query.hpp"
#include "input_error.hpp"
#include "visibility_soups.hpp"

namespace vsgl {
namespace {

class RayVisibilityTest : public test::GpuTest {
 protected:
  // The queries of `segments`, and the CPU's answers to them as the kernel writes them.
  static std::vector<gpu::SegmentQuery> queries_of(const std::vector<test::TestSegment>& segments) {
    std::vector<gpu::SegmentQuery> out;
    for (const test::TestSegment& s : segments) out.push_back(make_segment_query(s.from, s.to, s.epsilon));
    return out;
  }
  static std::vector<uint32_t> cpu_answers(const Bvh& bvh, const TriangleSoup& soup,
                                           const std::vector<gpu::SegmentQuery>& queries) {
    std::vector<uint32_t> out;
    for (const gpu::SegmentQuery& q : queries) out.push_back(segment_occluded(bvh, soup, q) ? 0u : 1u);
    return out;
  }
  // The message of the DeviceLimitError `f` throws ("" when none).
  template <class F>
  static std::string device_limit_error(F&& f) {
    try {
      f();
    } catch (const DeviceLimitError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no DeviceLimitError";
    return "";
  }
};

TEST_F(RayVisibilityTest, MatchesTheCpuTraversalBitForBit) {
  for (const uint32_t seed : {11u, 12u}) {
    for (const uint32_t size : {1u, 60u, 2000u}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(size) + " triangles");
      const TriangleSoup soup = test::random_soup(seed, size);
      const Bvh bvh = build_bvh(soup);
      const auto queries = queries_of(test::random_segments(soup, seed + 7, 3000));
      const std::vector<uint32_t> expected = cpu_answers(bvh, soup, queries);
      RayVisibility visibility(device(), bvh, soup);
      const std::vector<uint32_t> got = visibility.visible(queries);
      ASSERT_EQ(got.size(), expected.size());
      uint32_t mismatches = 0, occluded = 0;
      for (std::size_t i = 0; i < got.size(); ++i) {
        if (got[i] != expected[i] && ++mismatches <= 5)
          ADD_FAILURE() << "query " << i << " (kind " << i % 6 << "): GPU " << got[i] << ", CPU " << expected[i];
        occluded += expected[i] == 0u;
      }
      EXPECT_EQ(mismatches, 0u);
      EXPECT_EQ(visibility.dispatch_count(), 1u);
      if (size >= 60) {  // both answers common: the comparison is not vacuous
        EXPECT_GT(occluded, got.size() / 10);
        EXPECT_LT(occluded, got.size() * 9 / 10);
      }
    }
  }
}

TEST_F(RayVisibilityTest, OneOccluderGivesZeroAndItsAbsenceOne) {
  TriangleSoup soup;
  soup.vertices = {glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(2.0f, -1.0f, 0.0f), glm::vec3(-1.0f, 2.0f, 0.0f)};
  const glm::vec3 below(0.1f, 0.2f, -1.0f), above(0.1f, 0.2f, 1.0f), aside(5.1f, 0.2f, 1.0f);
  const std::vector<gpu::SegmentQuery> queries = {
      make_segment_query(below, above, 1e-4f),                        // through it
      make_segment_query(below, aside, 1e-4f),                        // crosses z = 0 at x = 2.6, beside it
      make_segment_query(glm::vec3(0.1f, 0.2f, 0.0f), above, 1e-4f),  // from its surface
      make_segment_query(glm::vec3(0.1f, 0.2f, 0.0f), above, 0.0f),   // from its surface, t = 0 exactly
  };
  RayVisibility visibility(device(), build_bvh(soup), soup);
  EXPECT_EQ(visibility.visible(queries), (std::vector<uint32_t>{0u, 1u, 1u, 1u}));
  RayVisibility nothing(device(), build_bvh(TriangleSoup{}), TriangleSoup{});
  EXPECT_EQ(nothing.visible(queries), (std::vector<uint32_t>{1u, 1u, 1u, 1u}));
  EXPECT_EQ(nothing.dispatch_count(), 0u) << "an empty scene needs no GPU";
}

// Dispatches of a few queries each (a small maxComputeWorkGroupCount) answer as one does.
TEST_F(RayVisibilityTest, ChunkedDispatchesAnswerAsOne) {
  const TriangleSoup soup = test::random_soup(21, 300);
  const Bvh bvh = build_bvh(soup);
  const auto queries = queries_of(test::random_segments(soup, 22, 1000));
  VisibilityLimits limits = visibility_limits(device().info());
  limits.max_group_count_x = 2;
  RayVisibility chunked(device(), bvh, soup, limits);
  ASSERT_EQ(chunked.queries_per_dispatch(), 2u * gpu::kVisibilityGroupSize);
  EXPECT_EQ(chunked.visible(queries), cpu_answers(bvh, soup, queries));
  EXPECT_EQ(chunked.dispatch_count(), (1000u + 127u) / 128u);
}

// The larger of the two buffers one byte over a (faked) maxStorageBufferRange is refused, naming
// the buffer, the limit, its value and the bytes asked, before any buffer, pipeline or dispatch is
// made; at the limit it runs.
TEST_F(RayVisibilityTest, ABvhBeyondMaxStorageBufferRangeIsRefused) {
  const TriangleSoup soup = test::random_soup(31, 500);
  const Bvh bvh = build_bvh(soup);
  const uint64_t node_bytes = bvh.nodes.size() * sizeof(gpu::BvhNode);
  const uint64_t triangle_bytes = soup.triangle_count() * sizeof(gpu::BvhTriangle);
  const uint64_t larger = std::max(node_bytes, triangle_bytes);
  const std::string buffer = node_bytes >= triangle_bytes ? "node buffer" : "triangle buffer";
  VisibilityLimits limits = visibility_limits(device().info());
  limits.storage_buffer_range = larger - 1;
  const std::string message = device_limit_error([&] { RayVisibility refused(device(), bvh, soup, limits); });
  EXPECT_NE(message.find(buffer + ": " + std::to_string(larger) + " bytes, and the device allows " +
                         std::to_string(larger - 1) + " (maxStorageBufferRange)"),
            std::string::npos)
      << message;
  limits.storage_buffer_range = std::min(node_bytes, triangle_bytes) - 1;
  const std::string both = device_limit_error([&] { RayVisibility refused(device(), bvh, soup, limits); });
  EXPECT_NE(both.find("node buffer: " + std::to_string(node_bytes) + " bytes"), std::string::npos) << both;

  limits.storage_buffer_range = larger;
  RayVisibility fits(device(), bvh, soup, limits);
  EXPECT_EQ(fits.dispatch_count(), 0u);
  const auto queries = queries_of(test::random_segments(soup, 32, 200));
  EXPECT_EQ(fits.visible(queries), cpu_answers(bvh, soup, queries));
  EXPECT_EQ(fits.dispatch_count(), 1u);
}

TEST_F(RayVisibilityTest, RefusesASoupTheBvhWasNotBuiltOver) {
  const TriangleSoup soup = test::random_soup(41, 50);
  TriangleSoup moved = soup;
  moved.vertices[10].x += 1.0f;
  const std::string message = test::input_error([&] { RayVisibility refused(device(), build_bvh(soup), moved); });
  EXPECT_NE(message.find("not built over this soup"), std::string::npos) << message;
}

// The limits check alone, without a device: each limit named with its value and the bytes asked.
TEST(VisibilityLimits, EachLimitIsCheckedAndNamed) {
  VisibilityLimits limits;
  limits.storage_buffer_range = 1000;
  limits.max_allocation = 4000;
  limits.device_local_bytes = 100000;
  limits.max_group_count_x = 65535;
  EXPECT_EQ(visibility_chunk_queries(limits), 1000u / sizeof(gpu::SegmentQuery));
  EXPECT_NO_THROW(require_visibility_buffers_fit(limits, 1000, 1000, "dev"));
  const auto message = [&](uint64_t nodes, uint64_t triangles) {
    try {
      require_visibility_buffers_fit(limits, nodes, triangles, "dev");
    } catch (const DeviceLimitError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(1001, 10),
            "dev cannot hold the BVH's node buffer: 1001 bytes, and the device allows 1000 (maxStorageBufferRange)");
  EXPECT_EQ(message(10, 1001),
            "dev cannot hold the BVH's triangle buffer: 1001 bytes, and the device allows 1000 "
            "(maxStorageBufferRange)");
  limits.storage_buffer_range = 10000;
  EXPECT_NE(message(4001, 10).find("4001 bytes, and the device allows 4000 (maxMemoryAllocationSize)"),
            std::string::npos);
  limits.max_allocation = 0;  // not reported: not checked
  EXPECT_EQ(message(9000, 9000), "");
  limits.device_local_bytes = 18000;
  EXPECT_NE(message(9000, 9000).find("(the device-local heap)"), std::string::npos);
  limits.storage_buffer_range = sizeof(gpu::SegmentQuery) - 1;
  EXPECT_EQ(visibility_chunk_queries(limits), 0u);
  EXPECT_NE(message(0, 0).find("cannot bind one segment query"), std::string::npos);
}

}  // namespace
}  // namespace vsgl
