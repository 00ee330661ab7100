#include "bench/cli/program_version.hpp"

#include <vulkan/vulkan.h>

#include "harness/core/build_info.hpp"
#include "harness/vk/device_info.hpp"

namespace vsgl::cli {

std::string vulkan_header_version() { return api_version_string(VK_HEADER_VERSION_COMPLETE); }

std::string program_version_text(const std::string& program) {
  return version_text(program) + "\nVulkan headers " + vulkan_header_version() + "\nlicence " + kLicence +
         " (the Apache License, Version 2.0)";
}

}  // namespace vsgl::cli
