#pragma once
// A render pass of one subpass that draws into colour attachments and one depth attachment,
// every attachment cleared when the pass begins; the colours are stored and end in
// `color_final_layout`, the depth is discarded. The caller gives the subpass dependencies.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "harness/vk/unique_handle.hpp"

namespace vsgl {

class Device;

struct RenderPassDesc {
  std::vector<VkFormat> color_formats;  // attachments 0..n-1
  VkImageLayout color_final_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkFormat depth_format = VK_FORMAT_UNDEFINED;  // attachment n
  std::vector<VkSubpassDependency> dependencies;
};

class RenderPass {
 public:
  RenderPass(Device& device, const RenderPassDesc& desc, const std::string& name);
  VkRenderPass get() const { return pass_.get(); }

 private:
  UniqueHandle<VkRenderPass> pass_;
};

}  // namespace vsgl
