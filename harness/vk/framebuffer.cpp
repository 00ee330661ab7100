#include "harness/vk/framebuffer.hpp"

#include "harness/vk/device.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {

Framebuffer::Framebuffer(Device& device, VkRenderPass pass, const std::vector<VkImageView>& attachments,
                         uint32_t width, uint32_t height, const std::string& name) {
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = pass;
  info.attachmentCount = static_cast<uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.width = width;
  info.height = height;
  info.layers = 1;
  VkFramebuffer fb = VK_NULL_HANDLE;
  VK_CHECK(vkCreateFramebuffer(device.get(), &info, nullptr, &fb));
  framebuffer_ = UniqueHandle<VkFramebuffer>(device.get(), fb, vkDestroyFramebuffer);
  device.set_name(fb, VK_OBJECT_TYPE_FRAMEBUFFER, name);
}

}  // namespace vsgl
