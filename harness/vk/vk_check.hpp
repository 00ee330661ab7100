#pragma once
// VK_CHECK: every Vulkan call that returns a VkResult goes through it. A failure throws
// VulkanError naming the call, where it was made and the VkResult, so that "out of device
// memory" or "device lost" reach the user as a sentence rather than a crash.
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace vsgl {

const char* vk_result_name(VkResult result);

class VulkanError : public std::runtime_error {
 public:
  VulkanError(VkResult result, const std::string& what) : std::runtime_error(what), result_(result) {}
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

[[noreturn]] void throw_vk_error(VkResult result, const char* call, const char* file, int line);

inline void vk_check(VkResult result, const char* call, const char* file, int line) {
  if (result != VK_SUCCESS) throw_vk_error(result, call, file, line);
}

}  // namespace vsgl

#define VK_CHECK(call) ::vsgl::vk_check((call), #call, __FILE__, __LINE__)
