// The validation fixture must be able to fail: an invalid call on a validated instance is
// counted as an error, so "zero errors" in every other test means something.
#include <gtest/gtest.h>

#include <cstdlib>

#include "gpu_test.hpp"
#include "harness/vk/device.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {
namespace {

TEST(ValidationLayer, CountsErrorsOfInvalidCalls) {
  if (!test::test_validation()) GTEST_SKIP() << "VSGL_TEST_VALIDATION=off: no validation layer to count errors with";
  GpuContextOptions options;
  options.instance.validation = true;
  options.instance.quiet_validation = true;
  const char* env = std::getenv("VSGL_TEST_DEVICE");
  options.device = env != nullptr ? env : "llvmpipe";
  GpuContext ctx(options);
  ASSERT_TRUE(ctx.instance().validation_enabled());
  EXPECT_EQ(ctx.instance().validation_errors(), 0u);
  // A buffer of size 0 is invalid usage (VUID-VkBufferCreateInfo-size-00912).
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  (void)vkCreateBuffer(ctx.device().get(), &info, nullptr, &buffer);
  if (buffer != VK_NULL_HANDLE) vkDestroyBuffer(ctx.device().get(), buffer, nullptr);
  EXPECT_GE(ctx.instance().validation_errors(), 1u);
}

TEST(ValidationLayer, ErrorsNameTheFailingCall) {
  try {
    VK_CHECK(VK_ERROR_DEVICE_LOST);
    FAIL() << "VK_CHECK did not throw";
  } catch (const VulkanError& e) {
    EXPECT_EQ(e.result(), VK_ERROR_DEVICE_LOST);
    EXPECT_NE(std::string(e.what()).find("VK_ERROR_DEVICE_LOST"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("device was lost"), std::string::npos);
  }
}

}  // namespace
}  // namespace vsgl

namespace vsgl {
namespace {

// The strict bit-for-bit GPU/CPU checks run where division is correctly rounded. CI runs on
// lavapipe, so there they must run: if this probe ever said otherwise they would silently relax.
TEST(DeviceProbe, LavapipeDividesExactlySoStrictChecksRunInCi) {
  const auto& info = test::shared_context().device().info();
  if (info.driver_name.find("llvmpipe") == std::string::npos) GTEST_SKIP() << "not lavapipe: " << info.name;
  EXPECT_TRUE(test::division_is_correctly_rounded());
}

}  // namespace
}  // namespace vsgl
