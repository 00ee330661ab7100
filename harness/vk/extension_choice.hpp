#pragma once
// Which instance and device extensions vsgl-bench enables, decided from the names the loader and
// the device list, apart from any Vulkan call so that the decision is testable without a
// portability driver (DESIGN.md §13).
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace vsgl {

// VK_KHR_portability_subset lives in vulkan_beta.h, which needs VK_ENABLE_BETA_EXTENSIONS; the
// name is all vsgl-bench needs of it.
inline constexpr const char* kPortabilitySubsetExtension = "VK_KHR_portability_subset";

struct InstanceExtensionChoice {
  std::vector<const char*> extensions;  // to pass as ppEnabledExtensionNames
  VkInstanceCreateFlags flags = 0;      // VkInstanceCreateInfo::flags
  bool debug_utils = false;             // VK_EXT_debug_utils is among `extensions`
  bool portability_enumeration = false;
};

// From the instance extensions the loader lists: VK_EXT_debug_utils where listed (object names;
// validation messages), and VK_KHR_portability_enumeration with
// VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR where listed, so that the loader also reports
// portability drivers such as MoltenVK (it hides them otherwise). Neither is enabled where it is
// not listed: the flag without the extension is an error.
InstanceExtensionChoice choose_instance_extensions(const std::vector<std::string>& available);

// From the extensions a physical device lists: VK_KHR_portability_subset where listed, since the
// specification requires a device that lists it to have it enabled (MoltenVK lists it).
std::vector<const char*> choose_device_extensions(const std::vector<std::string>& available);

}  // namespace vsgl
