#pragma once
// The fixture of every test that touches Vulkan: one context per test process, on lavapipe
// unless VSGL_TEST_DEVICE names another device, with the Khronos validation layer and
// synchronization validation on. A test fails if the layer reported any error during it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

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
