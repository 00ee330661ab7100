#pragma once
// The fixture of every test that touches Vulkan: one context per test process, on lavapipe
// unless VSGL_TEST_DEVICE names another device, with the Khronos validation layer and
// synchronization validation on. A test fails if the layer reported any error during it.
// VSGL_TEST_VALIDATION=off runs without the layer where none can be loaded: Wine's vulkan-1.dll
// loads no layer, so ci/windows-test.sh sets it for the Windows build (DESIGN.md §13.1).
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

#include <random>
#include <vector>

#include "harness/vk/buffer.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/vk/device.hpp"
#include "kernels/include/interface/testing.h"

namespace vsgl::test {

// tests/CMakeLists.txt labels a suite `gpu` by its name (*Test, *Cli, DeviceProbe,
// ValidationLayer) and everything else `cpu`, so that `ctest -L cpu` runs without a Vulkan
// device. A test that reaches the device from a suite named otherwise fails here, so the labels
// cannot silently go wrong.
inline bool suite_is_labelled_gpu(const std::string& suite) {
  const auto ends_with = [&](const char* tail) {
    const std::string t(tail);
    return suite.size() >= t.size() && suite.compare(suite.size() - t.size(), t.size(), t) == 0;
  };
  return ends_with("Test") || ends_with("Cli") || suite == "DeviceProbe" || suite == "ValidationLayer";
}

inline void require_gpu_label() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  if (info != nullptr && !suite_is_labelled_gpu(info->test_suite_name()))
    ADD_FAILURE() << "suite " << info->test_suite_name()
                  << " uses the Vulkan device but its name labels it `cpu` (tests/CMakeLists.txt): name it *Test or *Cli";
}

// False only when VSGL_TEST_VALIDATION is "off".
inline bool test_validation() {
  const char* env = std::getenv("VSGL_TEST_VALIDATION");
  return env == nullptr || std::string(env) != "off";
}

inline GpuContext& shared_context() {
  require_gpu_label();
  static std::unique_ptr<GpuContext> ctx = [] {
    GpuContextOptions options;
    options.instance.validation = test_validation();
    const char* env = std::getenv("VSGL_TEST_DEVICE");
    options.device = env != nullptr ? env : "llvmpipe";
    return std::make_unique<GpuContext>(options);
  }();
  return *ctx;
}

// Whether the device's float division is correctly rounded, measured on 4096 random quotients.
// SPIR-V allows 2.5 ULP; lavapipe is exact, NVIDIA's is not. Tests that demand bit-exact GPU/CPU
// agreement of division-dependent results (the sampler, k-means seeds) ask this first.
inline bool division_is_correctly_rounded() {
  static const bool exact = [] {
    Device& dev = shared_context().device();
    constexpr uint32_t kCount = 4096;
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> d(0.001f, 1000.0f);
    std::vector<float> pairs(2 * kCount);
    for (auto& v : pairs) v = d(rng);
    Buffer in(dev, pairs.size() * sizeof(float), MemoryUsage::kDeviceLocal, "test.division.pairs");
    Buffer out(dev, kCount * sizeof(float), MemoryUsage::kDeviceLocal, "test.division.quotients");
    upload(dev, in, pairs.data(), pairs.size() * sizeof(float));
    ComputePipeline pipeline(dev, {"test_division.comp", 2, sizeof(gpu::TestCountPush),
                                    work_group_size_1d(gpu::kTestGroupSize)});
    BindingSet set(dev, pipeline, {in, out}, "test.division.set");
    dev.submit_and_wait([&](VkCommandBuffer cmd) {
      CommandStream stream(cmd);
      stream.dispatch(pipeline, set, gpu::TestCountPush{kCount}, div_up(kCount, gpu::kTestGroupSize));
    });
    const auto q = download_vector<float>(dev, out, kCount);
    for (uint32_t i = 0; i < kCount; ++i)
      if (q[i] != pairs[2 * i] / pairs[2 * i + 1]) return false;
    return true;
  }();
  return exact;
}

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override {
    shared_context().instance().clear_validation_messages();
  }
  void TearDown() override {
    auto& instance = shared_context().instance();
    const auto messages = instance.validation_messages();
    std::string errors;
    for (const auto& m : messages)
      if (m.rfind("validation error", 0) == 0) errors += m + "\n";
    EXPECT_EQ(instance.validation_errors(), 0u) << "Khronos validation reported errors:\n" << errors;
  }
  Device& device() { return shared_context().device(); }
};

}  // namespace vsgl::test
