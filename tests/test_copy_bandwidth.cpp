// The physical limit of DESIGN.md §9: the copy-bandwidth measurement (harness/timing/copy_bandwidth.hpp)
// on the test device with a small size — only that it is a finite positive number with its
// bookkeeping consistent, never how fast — its size plan and options on hand-made limits, and the
// FIS passes' least-traffic model (harness/generators/fis/fis_traffic.hpp) by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_test.hpp"
#include "harness/core/error.hpp"
#include "harness/generators/fis/fis_traffic.hpp"
#include "harness/timing/copy_bandwidth.hpp"

namespace vsgl {
namespace {

class CopyBandwidthTest : public test::GpuTest {};

TEST_F(CopyBandwidthTest, SmallCopyGivesAFinitePositiveBandwidth) {
  CopyBandwidthOptions o;
  o.bytes = 1u << 20;
  o.copies = 3;
  const CopyBandwidth c = measure_copy_bandwidth(device(), o);
  EXPECT_EQ(c.requested_bytes, o.bytes);
  EXPECT_EQ(c.bytes, o.bytes);
  EXPECT_TRUE(c.reduced_because.empty()) << c.reduced_because;
  ASSERT_EQ(c.samples_ms.size(), 3u);
  for (double s : c.samples_ms) EXPECT_GT(s, 0.0);
  EXPECT_GT(c.median_ms, 0.0);
  EXPECT_TRUE(std::isfinite(c.bytes_per_s));
  EXPECT_GT(c.bytes_per_s, 0.0);
  EXPECT_DOUBLE_EQ(c.bytes_per_s, 2.0 * static_cast<double>(c.bytes) / (c.median_ms * 1e-3));  // read + written
}

TEST(CopyBandwidthPlan, SizeIsCappedByTheDevicesLimitsAndSaysWhy) {
  const uint64_t mib = 1u << 20;
  EXPECT_EQ(plan_copy_size(256 * mib, 0, 0).bytes, 256 * mib);  // no limits known
  EXPECT_TRUE(plan_copy_size(256 * mib, 0, 0).reduced_because.empty());
  EXPECT_EQ(plan_copy_size(256 * mib + 100, 0, 0).bytes, 256 * mib);  // whole 256-byte blocks
  const CopySizePlan alloc = plan_copy_size(256 * mib, 64 * mib, 0);
  EXPECT_EQ(alloc.bytes, 64 * mib);
  EXPECT_NE(alloc.reduced_because.find("maxMemoryAllocationSize"), std::string::npos);
  const CopySizePlan heap = plan_copy_size(256 * mib, 0, 512 * mib);  // 2 x 128 MiB = half the heap
  EXPECT_EQ(heap.bytes, 128 * mib);
  EXPECT_NE(heap.reduced_because.find("heap"), std::string::npos);
  EXPECT_TRUE(plan_copy_size(256 * mib, 1024 * mib, 8192 * mib).reduced_because.empty());

  CopyBandwidthOptions o;
  EXPECT_NO_THROW(o.check());
  o.copies = 0;
  EXPECT_THROW(o.check(), UsageError);
  o = CopyBandwidthOptions{};
  o.bytes = 1024;
  EXPECT_THROW(o.check(), UsageError);
  o = CopyBandwidthOptions{};
  o.min_bytes = o.bytes * 2;
  EXPECT_THROW(o.check(), UsageError);
}

TEST(FisTraffic, LeastBytesByHand) {
  // 3 x 2 texels: S = 4, L = 2; levels 3x2 (6), 2x1 (2), 1x1 (1).
  const FisPassBytes b = fis_minimum_bytes(3, 2);
  EXPECT_EQ(b.additional.read, 6u * 15u * 4u);  // 15 float32 capture channels
  EXPECT_EQ(b.additional.written, 6u * 80u);    // 5 vec4 float32 moment layers
  EXPECT_EQ(b.mipmapping.read, 6u * 80u);       // level 0 once
  EXPECT_EQ(b.mipmapping.written, (2u + 1u) * 80u);
  EXPECT_EQ(b.mipmapping_level_by_level.read, (6u + 2u) * 80u);
  EXPECT_EQ(b.mipmapping_level_by_level.written, (2u + 1u) * 80u);
  EXPECT_EQ(b.additional.total(), b.additional.read + b.additional.written);
  // The paper's G-buffer: 1920 x 1088 texels, S = 2048, L = 11.
  const FisPassBytes g = fis_minimum_bytes(1920, 1088);
  EXPECT_EQ(g.additional.total(), 1920ull * 1088 * 140);
  uint64_t upper = 0;
  for (uint32_t l = 1; l <= 11; ++l) upper += uint64_t{((1920u - 1) >> l) + 1} * (((1088u - 1) >> l) + 1);
  EXPECT_EQ(g.mipmapping.written, upper * 80);
  EXPECT_LT(g.mipmapping.written, g.mipmapping.read / 3 + 80 * 64);  // about a third of level 0
  EXPECT_FALSE(fis_traffic_model().empty());
  EXPECT_THROW(fis_minimum_bytes(0, 4), InputError);
}

}  // namespace
}  // namespace vsgl
