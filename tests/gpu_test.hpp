#pragma once
// The fixture of every test that touches Vulkan: one context per test process, on lavapipe
// unless VSGL_TEST_DEVICE names another device, with the Khronos validation layer and
// synchronization validation on. A test fails if the layer reported any error during it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

#include <random>
#include <vector>

#include "harness/buffer.hpp"
#include "harness/command_stream.hpp"
#include "harness/compute_pipeline.hpp"
#include "harness/device.hpp"

namespace vsgl::test {

inline GpuContext& shared_context() {
  static std::unique_ptr<GpuContext> ctx = [] {
    GpuContextOptions options;
    options.instance.validation = true;
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
    ComputePipeline pipeline(dev, {"test_division.comp", 2, sizeof(uint32_t), {}});
    BindingSet set(dev, pipeline, {in, out}, "test.division.set");
    dev.submit_and_wait([&](VkCommandBuffer cmd) {
      CommandStream stream(cmd);
      stream.dispatch(pipeline, set, kCount, div_up(kCount, 64));
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
