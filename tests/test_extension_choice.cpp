// The instance and device extensions vsgl-bench enables (DESIGN.md §13), decided from extension
// lists alone: the portability paths (MoltenVK) are checked here without a portability driver.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "harness/vk/extension_choice.hpp"

namespace vsgl {
namespace {

bool lists(const std::vector<const char*>& names, const char* name) {
  for (const char* n : names)
    if (std::strcmp(n, name) == 0) return true;
  return false;
}

TEST(ExtensionChoice, PortabilityEnumerationOnlyWhereTheLoaderListsIt) {
  // A loader older than 1.3.216 does not list it: no extension, and no flag (the flag alone is an error).
  const InstanceExtensionChoice plain =
      choose_instance_extensions({"VK_KHR_surface", VK_EXT_DEBUG_UTILS_EXTENSION_NAME, "VK_KHR_xcb_surface"});
  EXPECT_FALSE(plain.portability_enumeration);
  EXPECT_EQ(plain.flags, 0u);
  EXPECT_FALSE(lists(plain.extensions, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME));

  // A loader that lists it (Debian 12's, the Vulkan SDK's on macOS): the extension and the flag together.
  const InstanceExtensionChoice portable = choose_instance_extensions(
      {"VK_KHR_surface", VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME, VK_EXT_DEBUG_UTILS_EXTENSION_NAME});
  EXPECT_TRUE(portable.portability_enumeration);
  EXPECT_EQ(portable.flags, static_cast<VkInstanceCreateFlags>(VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR));
  EXPECT_TRUE(lists(portable.extensions, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME));
}

TEST(ExtensionChoice, DebugUtilsOnlyWhereListedAndNothingElseEnabled) {
  const InstanceExtensionChoice with = choose_instance_extensions({VK_EXT_DEBUG_UTILS_EXTENSION_NAME});
  EXPECT_TRUE(with.debug_utils);
  ASSERT_EQ(with.extensions.size(), 1u);
  EXPECT_STREQ(with.extensions[0], VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

  // Unrelated extensions are never enabled, and an empty list enables nothing.
  const InstanceExtensionChoice none = choose_instance_extensions({"VK_KHR_surface", "VK_KHR_display"});
  EXPECT_FALSE(none.debug_utils);
  EXPECT_TRUE(none.extensions.empty());
  EXPECT_EQ(none.flags, 0u);
  EXPECT_TRUE(choose_instance_extensions({}).extensions.empty());
  // A name must match whole: a longer name that starts like it is another extension.
  EXPECT_FALSE(choose_instance_extensions({"VK_KHR_portability_enumeration2"}).portability_enumeration);
}

TEST(ExtensionChoice, PortabilitySubsetEnabledExactlyWhereTheDeviceListsIt) {
  // A MoltenVK-like device lists it among others: it alone is enabled.
  const std::vector<const char*> moltenvk =
      choose_device_extensions({"VK_KHR_swapchain", "VK_KHR_portability_subset", "VK_EXT_memory_budget"});
  ASSERT_EQ(moltenvk.size(), 1u);
  EXPECT_STREQ(moltenvk[0], "VK_KHR_portability_subset");
  EXPECT_STREQ(kPortabilitySubsetExtension, "VK_KHR_portability_subset");

  // A conformant desktop device or lavapipe does not list it: nothing is enabled.
  EXPECT_TRUE(choose_device_extensions({"VK_KHR_swapchain", "VK_EXT_memory_budget"}).empty());
  EXPECT_TRUE(choose_device_extensions({}).empty());
}

}  // namespace
}  // namespace vsgl
