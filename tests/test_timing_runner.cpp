// The timing harness (harness/timing/timing_runner.hpp): it refuses a device without timestamps and a
// zero interval, replays a once-recorded command buffer with a timestamp at every phase boundary,
// runs the round-robin schedule and the stop rule, and its dispatch counts (Table 3) equal the
// vkCmdDispatch calls actually recorded, counted here independently by wrapping the Vulkan entry
// points, as the number of kernels per generator equals the distinct pipelines bound.
#include <gtest/gtest.h>
#ifdef _WIN32
#include <windows.h>
#else
#include <dlfcn.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstring>
#include <limits>
#include <set>

#include "gpu_test.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/core/error.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/measured_table.hpp"
#include "harness/scene/scene.hpp"
#include "harness/vk/buffer.hpp"
#include "kernels/include/interface/testing.h"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/vk/timestamp_pool.hpp"
#include "harness/timing/timing_runner.hpp"

// ---- independent counting: these definitions take precedence over libvulkan's (on Windows over
// the import library's thunks) for every call the harness makes from this executable, and forward
// to the loader's: the next definition (RTLD_NEXT), or vulkan-1.dll's export. ----
namespace {
template <class Function>
Function loader_function(const char* name) {
#ifdef _WIN32
  return reinterpret_cast<Function>(reinterpret_cast<void*>(GetProcAddress(GetModuleHandleW(L"vulkan-1.dll"), name)));
#else
  return reinterpret_cast<Function>(dlsym(RTLD_NEXT, name));
#endif
}

std::atomic<bool> g_counting{false};
std::atomic<uint32_t> g_dispatches{0};
std::set<VkPipeline>* g_pipelines = nullptr;
std::set<VkPipeline>* g_created = nullptr;  // compute pipelines created while it is set
}  // namespace

extern "C" VKAPI_ATTR void VKAPI_CALL vkCmdDispatch(VkCommandBuffer cmd, uint32_t x, uint32_t y, uint32_t z) {
  static const auto next = loader_function<PFN_vkCmdDispatch>("vkCmdDispatch");
  if (g_counting) ++g_dispatches;
  next(cmd, x, y, z);
}

extern "C" VKAPI_ATTR void VKAPI_CALL vkCmdBindPipeline(VkCommandBuffer cmd, VkPipelineBindPoint point,
                                                        VkPipeline pipeline) {
  static const auto next = loader_function<PFN_vkCmdBindPipeline>("vkCmdBindPipeline");
  if (g_counting && g_pipelines != nullptr && point == VK_PIPELINE_BIND_POINT_COMPUTE) g_pipelines->insert(pipeline);
  next(cmd, point, pipeline);
}

extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkCreateComputePipelines(VkDevice device, VkPipelineCache cache,
                                                                   uint32_t count,
                                                                   const VkComputePipelineCreateInfo* infos,
                                                                   const VkAllocationCallbacks* allocator,
                                                                   VkPipeline* pipelines) {
  static const auto next = loader_function<PFN_vkCreateComputePipelines>("vkCreateComputePipelines");
  const VkResult result = next(device, cache, count, infos, allocator, pipelines);
  if (result == VK_SUCCESS && g_created != nullptr) g_created->insert(pipelines, pipelines + count);
  return result;
}

namespace vsgl {
namespace {

TEST(TimingChecks, DeviceWithoutTimestampsIsRefused) {
  DeviceInfo info;
  info.name = "fake device";
  info.timestamp_valid_bits = 0;
  info.timestamp_period_ns = 1.0f;
  try {
    require_timestamps(info);
    FAIL() << "a device without timestamp bits was accepted";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("timestampValidBits = 0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("fake device"), std::string::npos) << e.what();
  }
  info.timestamp_valid_bits = 64;
  info.timestamp_period_ns = 0.0f;
  EXPECT_THROW(require_timestamps(info), DeviceError);
  info.timestamp_period_ns = 1.0f;
  EXPECT_NO_THROW(require_timestamps(info));
}

TEST(TimingChecks, ZeroIntervalIsAnErrorNotANumber) {
  const uint64_t mask = TimestampPool::mask_for_bits(36);
  EXPECT_THROW(TimestampPool::interval_ns(1000, 1000, mask, 1.0), DeviceError);
  EXPECT_THROW(TimestampPool::interval_ns(1000, 999, mask, 1.0), DeviceError);  // negative, seen through the wrap
  // mask-1 -> mask -> 0 -> 1 -> 2 -> 3: 5 ticks through the wrap, 2 ns each.
  EXPECT_DOUBLE_EQ(TimestampPool::interval_ns(mask - 1, 3, mask, 2.0), 10.0);
}

TEST(TimingChecks, OptionsBelowTheProtocolAreUsageErrors) {
  TimingOptions o;
  EXPECT_NO_THROW(o.check());
  o.warmup = 1;
  EXPECT_THROW(o.check(), UsageError);
  o = TimingOptions{};
  o.min_repetitions = 1;
  EXPECT_THROW(o.check(), UsageError);
  o = TimingOptions{};
  o.max_repetitions = 5;  // < min 10
  EXPECT_THROW(o.check(), UsageError);
  o = TimingOptions{};
  o.noise_target = 0.0;
  EXPECT_THROW(o.check(), UsageError);
  DeviceInfo cpu;
  cpu.type = VK_PHYSICAL_DEVICE_TYPE_CPU;
  DeviceInfo gpu;
  gpu.type = VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
  EXPECT_LT(TimingOptions::defaults_for(cpu).time_cap_s, TimingOptions::defaults_for(gpu).time_cap_s);
  EXPECT_EQ(TimingOptions::defaults_for(gpu).warmup, 2u);
  EXPECT_EQ(TimingOptions::defaults_for(gpu).min_repetitions, 10u);
}

class TimingRunnerTest : public test::GpuTest {
 protected:
  Capture tiny_capture() {
    CaptureRecorder recorder(device());
    Capture c = recorder.record(make_scene("tiny"), RecordSizes{96, 64, 64}, 0, 1);
    for (std::size_t i = 0; i < c.rsm.texels(); ++i)  // a stand-in light-view PDF: the flux
      c.rsm.planes[kPdf][i] = c.rsm.planes[kDR][i] + c.rsm.planes[kDG][i] + c.rsm.planes[kDB][i];
    c.rsm.has_pdf = true;
    return c;
  }
};

TEST_F(TimingRunnerTest, RoundRobinSamplesEveryPhaseAndCountsDispatchesTruly) {
  const Capture capture = tiny_capture();
  const DeviceView camera = upload_view(device(), capture, ViewKind::kCamera);
  const DeviceView light = upload_view(device(), capture, ViewKind::kLight);
  GeneratorConfig cfg;
  cfg.vsgl_count = 32;
  std::vector<std::unique_ptr<VsglGenerator>> gens;
  TimingOptions options;
  options.min_repetitions = 4;
  options.max_repetitions = 4;
  TimingRunner runner(device(), options);
  std::vector<uint32_t> counted_dispatches;
  std::vector<std::size_t> counted_pipelines;
  std::vector<std::set<VkPipeline>> created_pipelines, bound_pipelines;
  std::vector<std::string> names;
  for (const char* name : {"fis_tok15", "fis_modified", "kmeans_2d", "kmeans_3d_segsum"})
    for (const DeviceView* view : {&camera, &light}) {
      std::set<VkPipeline> created;
      g_created = &created;
      gens.push_back(make_generator(name, device(), *view, cfg));
      g_created = nullptr;
      created_pipelines.push_back(created);
      std::set<VkPipeline> pipelines;
      g_pipelines = &pipelines;
      g_dispatches = 0;
      g_counting = true;
      runner.add(TimingCase{name, view_name(view->kind), gens.back().get()});
      g_counting = false;
      g_pipelines = nullptr;
      counted_dispatches.push_back(g_dispatches);
      counted_pipelines.push_back(pipelines.size());
      bound_pipelines.push_back(pipelines);
      names.push_back(name);
    }
  for (std::size_t i = 0; i < names.size(); ++i) {
    SCOPED_TRACE(names[i]);
    EXPECT_GT(counted_dispatches[i], 0u);
    EXPECT_EQ(runner.dispatch_count(i), counted_dispatches[i]);
    // Table 3 "compute shaders" = the generator's kernels (generator_sources) under the config the
    // run takes (FIS: its pyramid path and this device's mip strategy): the generator builds one
    // pipeline from each, and binds only pipelines it built. FIS binds all of them on any view;
    // k-means skips its scan_add kernel when a scan fits one workgroup, as on this tiny view, so
    // there it binds exactly one fewer.
    const std::size_t kernels = generator_sources(names[i], resolve_fis_config(device().info(), cfg)).kernels.size();
    EXPECT_EQ(created_pipelines[i].size(), kernels);
    EXPECT_TRUE(std::includes(created_pipelines[i].begin(), created_pipelines[i].end(), bound_pipelines[i].begin(),
                              bound_pipelines[i].end()));
    const bool fis = generator_descriptor(names[i]).family == GeneratorFamily::kFis;
    EXPECT_EQ(counted_pipelines[i], fis ? kernels : kernels - 1);
  }

  const TimingResult r = runner.run();
  EXPECT_EQ(r.repetitions, 4u);
  EXPECT_FALSE(r.stop_reason.empty());
  ASSERT_EQ(r.cases.size(), names.size());
  for (std::size_t i = 0; i < r.cases.size(); ++i) {
    const CaseTiming& c = r.cases[i];
    EXPECT_EQ(c.generator, names[i]);
    EXPECT_EQ(c.dispatch_count, counted_dispatches[i]);
    ASSERT_EQ(c.phase_ms.size(), 3u);
    ASSERT_EQ(c.total_ms.size(), 4u);
    for (std::size_t rep = 0; rep < 4; ++rep) {
      double sum = 0;
      for (const auto& phase : c.phase_ms) {
        ASSERT_EQ(phase.size(), 4u);
        EXPECT_GT(phase[rep], 0.0);
        EXPECT_TRUE(std::isfinite(phase[rep]));
        sum += phase[rep];
      }
      EXPECT_DOUBLE_EQ(c.total_ms[rep], sum);
    }
    // Table 3's split of the dispatches: k-means' Lloyd iterations, nothing for FIS.
    const IterationDispatches d = iteration_dispatches(c);
    EXPECT_EQ(d.iterations * d.per_iteration + d.outside, counted_dispatches[i]);
    if (generator_descriptor(names[i]).family == GeneratorFamily::kKmeans) {
      EXPECT_EQ(d.iterations, cfg.kmeans_iterations);
      EXPECT_GT(d.per_iteration, 0u);
      EXPECT_GT(d.outside, 0u);
    } else {
      EXPECT_EQ(d.iterations, 0u);
    }
  }
}

// The dispatches per iteration that Table 3 reports are what one more Lloyd iteration adds to the
// vkCmdDispatch calls counted by the wrapper.
TEST_F(TimingRunnerTest, KmeansDispatchesPerIterationAreWhatAnIterationAdds) {
  const Capture capture = tiny_capture();
  const DeviceView camera = upload_view(device(), capture, ViewKind::kCamera);
  TimingOptions options;
  TimingRunner runner(device(), options);
  std::vector<std::unique_ptr<VsglGenerator>> gens;
  std::vector<uint32_t> counted;
  for (uint32_t iterations : {0u, 1u, 3u}) {
    GeneratorConfig cfg;
    cfg.vsgl_count = 32;
    cfg.kmeans_iterations = iterations;
    gens.push_back(make_generator("kmeans_2d", device(), camera, cfg));
    g_dispatches = 0;
    g_counting = true;
    runner.add(TimingCase{"kmeans_2d", "camera_view", gens.back().get()});
    g_counting = false;
    counted.push_back(g_dispatches);
    EXPECT_EQ(runner.iteration_dispatches(counted.size() - 1).size(), iterations);
  }
  ASSERT_EQ(runner.iteration_dispatches(1).size(), 1u);
  const uint32_t per_iteration = runner.iteration_dispatches(1).front();
  EXPECT_EQ(counted[1] - counted[0], per_iteration);
  EXPECT_EQ(counted[2] - counted[0], 3 * per_iteration);
  for (std::size_t i = 0; i < 3; ++i) {
    CaseTiming c;
    c.dispatch_count = runner.dispatch_count(i);
    c.iteration_dispatches = runner.iteration_dispatches(i);
    EXPECT_EQ(iteration_dispatches(c).outside, counted[0]);  // the same work around the iterations
  }
}

TEST_F(TimingRunnerTest, StopsAtTheNoiseTargetOrTheCapButNeverBeforeTheMinimum) {
  const Capture capture = tiny_capture();
  const DeviceView light = upload_view(device(), capture, ViewKind::kLight);
  GeneratorConfig cfg;
  cfg.vsgl_count = 16;
  auto gen = make_generator("fis_modified", device(), light, cfg);
  TimingOptions loose;
  loose.min_repetitions = 3;
  loose.noise_target = 1e9;  // any noise passes: stop exactly at the minimum
  TimingRunner a(device(), loose);
  a.add(TimingCase{"fis_modified", "light_view", gen.get()});
  uint32_t calls = 0;
  const TimingResult ra = a.run([&](const TimingProgress&) { ++calls; });
  EXPECT_EQ(ra.repetitions, 3u);
  EXPECT_EQ(ra.stop_reason, "noise_target");
  EXPECT_EQ(calls, loose.warmup + 3u);

  TimingOptions capped;
  capped.min_repetitions = 3;
  capped.noise_target = 1e-12;  // unreachable
  capped.time_cap_s = 0.0;      // ... so the cap stops it, after the minimum
  TimingRunner b(device(), capped);
  b.add(TimingCase{"fis_modified", "light_view", gen.get()});
  const TimingResult rb = b.run();
  EXPECT_EQ(rb.repetitions, 3u);
  EXPECT_EQ(rb.stop_reason, "time_cap");
}

// A one-phase case whose work is chosen per round by the host: kernels/test_workload.comp dispatched
// indirectly from a host-visible buffer that the test rewrites between rounds, so the same
// recording does little work in some rounds and ~1000x more in others.
using WorkloadPush = gpu::TestWorkloadPush;  // kernels/test_workload.comp

class RoundWorkload final : public VsglGenerator {
 public:
  static constexpr uint32_t kLocal = 64;
  static constexpr uint32_t kMaxGroups = 256;
  RoundWorkload(Device& device, const Buffer& groups, const std::string& name)
      : name_(name),
        groups_(groups),
        out_(device, VkDeviceSize{kMaxGroups} * kLocal * sizeof(uint32_t), MemoryUsage::kDeviceLocal, name + ".out"),
        pipeline_(device, {"test_workload.comp", 1, sizeof(WorkloadPush), {{0, kLocal}}}),
        set_(device, pipeline_, {out_}, name + ".set") {}
  std::string name() const override { return name_; }
  std::vector<std::string> phases() const override { return {"work"}; }
  const Buffer& vsgls() const override { return out_; }
  uint32_t vsgl_count() const override { return 0; }
  void record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) override {
    VkCommandBuffer cmd = stream.get();
    boundary(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    VkDescriptorSet ds = set_.get();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.layout(), 0, 1, &ds, 0, nullptr);
    const WorkloadPush push{kMaxGroups * kLocal, 4096};
    vkCmdPushConstants(cmd, pipeline_.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatchIndirect(cmd, groups_.get(), 0);
    boundary(cmd);
  }

 private:
  std::string name_;
  const Buffer& groups_;
  Buffer out_;
  ComputePipeline pipeline_;
  BindingSet set_;
};

// The pairing guarantee of timing_runner.hpp: sample i of every case is round i. Rounds 1, 3, 4
// (of 0..5) are heavy for both cases, the others light; each case's heavy-round samples must
// carry that pattern, which a case whose samples were shifted against the rounds, reordered or
// short of one would not (each of its two sets would then hold a light round). Judged on the
// fastest sample of each set (a 256x difference in work): a descheduled replay only adds time, so
// it cannot flip the verdict unless every light round of a case is slowed by a third of a heavy one.
TEST_F(TimingRunnerTest, SampleIOfEveryCaseIsRoundI) {
  Buffer groups(device(), sizeof(VkDispatchIndirectCommand), MemoryUsage::kUpload, "test.round_groups",
                VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
  const auto set_groups = [&](uint32_t x) {
    const VkDispatchIndirectCommand c{x, 1, 1};
    std::memcpy(groups.mapped(), &c, sizeof c);
  };
  const std::set<uint32_t> heavy{1, 3, 4};
  const uint32_t rounds = 6;
  RoundWorkload a(device(), groups, "pair_a"), b(device(), groups, "pair_b");
  TimingOptions options;
  options.min_repetitions = rounds;
  options.max_repetitions = rounds;
  TimingRunner runner(device(), options);
  runner.add(TimingCase{"pair_a", "light_view", &a});
  runner.add(TimingCase{"pair_b", "light_view", &b});
  set_groups(1);  // warm-up and round 0: light
  const TimingResult r = runner.run([&](const TimingProgress& p) {
    // Called after every warm-up and every round; p.rounds rounds are done, the next is p.rounds.
    set_groups(heavy.contains(p.rounds) ? RoundWorkload::kMaxGroups : 1);
  });
  ASSERT_EQ(r.repetitions, rounds);
  for (const CaseTiming& c : r.cases) {
    SCOPED_TRACE(c.generator);
    ASSERT_EQ(c.total_ms.size(), rounds);
    ASSERT_EQ(c.phase_ms.at(0).size(), rounds);
    double fastest_heavy_ms = std::numeric_limits<double>::infinity(), fastest_light_ms = fastest_heavy_ms;
    for (uint32_t i = 0; i < rounds; ++i) {
      double& fastest = heavy.contains(i) ? fastest_heavy_ms : fastest_light_ms;
      fastest = std::min(fastest, c.total_ms[i]);
    }
    EXPECT_GT(fastest_heavy_ms, 3.0 * fastest_light_ms)
        << "fastest heavy round " << fastest_heavy_ms << " ms, fastest light round " << fastest_light_ms << " ms";
  }
}

}  // namespace
}  // namespace vsgl
