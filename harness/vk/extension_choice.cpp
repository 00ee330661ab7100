#include "harness/vk/extension_choice.hpp"

#include <algorithm>

namespace vsgl {
namespace {

bool lists(const std::vector<std::string>& available, const char* name) {
  return std::find(available.begin(), available.end(), name) != available.end();
}

}  // namespace

InstanceExtensionChoice choose_instance_extensions(const std::vector<std::string>& available) {
  InstanceExtensionChoice choice;
  if (lists(available, VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
    choice.extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    choice.debug_utils = true;
  }
  if (lists(available, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
    choice.extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
    choice.flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    choice.portability_enumeration = true;
  }
  return choice;
}

std::vector<const char*> choose_device_extensions(const std::vector<std::string>& available) {
  std::vector<const char*> extensions;
  if (lists(available, kPortabilitySubsetExtension)) extensions.push_back(kPortabilitySubsetExtension);
  return extensions;
}

}  // namespace vsgl
