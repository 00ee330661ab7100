#pragma once
// A framebuffer: the image views one render pass draws into, in its attachment order.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "harness/vk/unique_handle.hpp"

namespace vsgl {

class Device;

class Framebuffer {
 public:
  Framebuffer(Device& device, VkRenderPass pass, const std::vector<VkImageView>& attachments, uint32_t width,
              uint32_t height, const std::string& name);
  VkFramebuffer get() const { return framebuffer_.get(); }

 private:
  UniqueHandle<VkFramebuffer> framebuffer_;
};

}  // namespace vsgl
