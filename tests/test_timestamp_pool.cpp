// The timestamp facility of SPEC §9 on a real queue, and its arithmetic without one.
#include <gtest/gtest.h>

#include "gpu_test.hpp"
#include "harness/vk/buffer.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/core/error.hpp"
#include "harness/vk/timestamp_pool.hpp"
#include "harness/vk/unique_handle.hpp"
#include "harness/vk/vk_check.hpp"
#include "kernels/include/interface/testing.h"

namespace vsgl {
namespace {

using test::GpuTest;

using gpu::kTestGroupSize;
using WorkloadPush = gpu::TestWorkloadPush;

TEST(TimestampArithmetic, WrapMaskAndPeriod) {
  EXPECT_EQ(TimestampPool::mask_for_bits(64), ~uint64_t{0});
  EXPECT_EQ(TimestampPool::mask_for_bits(36), (uint64_t{1} << 36) - 1);
  // 100 ticks at 1.5 ns.
  EXPECT_DOUBLE_EQ(TimestampPool::interval_ns(1000, 1100, TimestampPool::mask_for_bits(64), 1.5), 150.0);
  // A counter of 36 valid bits that wrapped between the two writes.
  const uint64_t mask = TimestampPool::mask_for_bits(36);
  EXPECT_DOUBLE_EQ(TimestampPool::interval_ns(mask - 9, 10, mask, 1.0), 20.0);
}

TEST(TimestampArithmetic, ZeroAndNegativeIntervalsAreErrors) {
  const uint64_t mask = TimestampPool::mask_for_bits(64);
  EXPECT_THROW(TimestampPool::interval_ns(500, 500, mask, 1.0), DeviceError);
  EXPECT_THROW(TimestampPool::interval_ns(500, 400, mask, 1.0), DeviceError);
}

class TimestampPoolTest : public GpuTest {};

// Three phases, light / heavy / light: the heavy one must dominate both neighbours. A driver that
// resolves timestamps lazily (lavapipe reads the clock at its next flush) shifts every phase's time
// onto a neighbour unless the pool orders the write on both sides; this test catches either shift.
TEST_F(TimestampPoolTest, EachIntervalTimesItsOwnPhase) {
  Device& dev = device();
  ASSERT_TRUE(dev.info().timestamps());
  const uint32_t count = 1u << 16;
  Buffer out(dev, count * sizeof(uint32_t), MemoryUsage::kDeviceLocal, "test.workload.out");
  ComputePipeline pipeline(dev, {"test_workload.comp", 1, sizeof(WorkloadPush), work_group_size_1d(kTestGroupSize)});
  BindingSet set(dev, pipeline, {out}, "test.workload.set");
  TimestampPool pool(dev, 4, "test.timestamps");

  auto run = [&](uint32_t heavy_iterations) {
    dev.submit_and_wait([&](VkCommandBuffer cmd) {
      CommandStream stream(cmd);
      pool.reset(cmd);
      pool.write(cmd);
      stream.dispatch(pipeline, set, WorkloadPush{count, 8}, div_up(count, kTestGroupSize));
      pool.write(cmd);
      stream.dispatch(pipeline, set, WorkloadPush{count, heavy_iterations}, div_up(count, kTestGroupSize));
      pool.write(cmd);
      stream.dispatch(pipeline, set, WorkloadPush{count, 8}, div_up(count, kTestGroupSize));
      pool.write(cmd);
      EXPECT_EQ(stream.dispatch_count(), 3u);
    });
    return pool.read_ticks();
  };
  run(8);  // warm-up: the first dispatch pays the driver's shader compilation (SPEC §9)
  // Grow the heavy phase until it takes at least 1 ms on this device, so that it dwarfs the
  // fixed cost of a dispatch and a barrier on a GPU as on a CPU driver.
  uint32_t heavy_iterations = 256;
  std::vector<uint64_t> ticks = run(heavy_iterations);
  while (pool.interval_ns(ticks[1], ticks[2]) < 1e6 && heavy_iterations < (1u << 24)) {
    heavy_iterations *= 4;
    ticks = run(heavy_iterations);
  }
  ASSERT_EQ(ticks.size(), 4u);
  const double light_before = pool.interval_ns(ticks[0], ticks[1]);
  const double heavy = pool.interval_ns(ticks[1], ticks[2]);
  const double light_after = pool.interval_ns(ticks[2], ticks[3]);
  EXPECT_GT(light_before, 0.0);
  EXPECT_GT(heavy, 8.0 * light_before) << "light " << light_before << " ns, heavy " << heavy << " ns";
  EXPECT_GT(heavy, 8.0 * light_after) << "heavy " << heavy << " ns, light " << light_after << " ns";
  // The work really ran: check one value against the same hash on the host.
  const auto values = download_vector<uint32_t>(dev, out, count);
  uint32_t h = 7u * 2654435761u + 1u;
  for (uint32_t k = 0; k < 8; ++k) h = (h ^ (h >> 15)) * 2246822519u + k;
  EXPECT_EQ(values[7], h);
}

TEST_F(TimestampPoolTest, PipelineStatisticsCountTheDispatchedInvocations) {
  Device& dev = device();
  if (!dev.pipeline_statistics_enabled()) GTEST_SKIP() << "device has no pipeline statistics queries";
  const uint32_t count = 1000;  // not a multiple of the group size: the tail group still runs
  const uint32_t local = kTestGroupSize;
  Buffer out(dev, count * sizeof(uint32_t), MemoryUsage::kDeviceLocal, "test.stats.out");
  ComputePipeline pipeline(dev, {"test_workload.comp", 1, sizeof(WorkloadPush), work_group_size_1d(local)});
  BindingSet set(dev, pipeline, {out}, "test.stats.set");

  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
  info.queryCount = 1;
  info.pipelineStatistics = VK_QUERY_PIPELINE_STATISTIC_COMPUTE_SHADER_INVOCATIONS_BIT;
  VkQueryPool raw = VK_NULL_HANDLE;
  VK_CHECK(vkCreateQueryPool(dev.get(), &info, nullptr, &raw));
  UniqueHandle<VkQueryPool> stats(dev.get(), raw, vkDestroyQueryPool);

  dev.submit_and_wait([&](VkCommandBuffer cmd) {
    CommandStream stream(cmd);
    vkCmdResetQueryPool(cmd, stats.get(), 0, 1);
    vkCmdBeginQuery(cmd, stats.get(), 0, 0);
    stream.dispatch(pipeline, set, WorkloadPush{count, 1}, div_up(count, local));
    vkCmdEndQuery(cmd, stats.get(), 0);
  });
  uint64_t invocations = 0;
  VK_CHECK(vkGetQueryPoolResults(dev.get(), stats.get(), 0, 1, sizeof invocations, &invocations, sizeof invocations,
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  EXPECT_EQ(invocations, uint64_t{div_up(count, local)} * local);
}

}  // namespace
}  // namespace vsgl
