#include "harness/vk/render_pass.hpp"

#include "harness/vk/device.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {

RenderPass::RenderPass(Device& device, const RenderPassDesc& desc, const std::string& name) {
  const auto colors = static_cast<uint32_t>(desc.color_formats.size());
  std::vector<VkAttachmentDescription> attachments(colors + 1);
  for (uint32_t i = 0; i < colors; ++i) {
    attachments[i].format = desc.color_formats[i];
    attachments[i].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[i].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[i].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[i].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[i].finalLayout = desc.color_final_layout;
  }
  auto& depth = attachments[colors];
  depth.format = desc.depth_format;
  depth.samples = VK_SAMPLE_COUNT_1_BIT;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  depth.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;

  std::vector<VkAttachmentReference> color_refs(colors);
  for (uint32_t i = 0; i < colors; ++i) color_refs[i] = {i, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth_ref{colors, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = colors;
  subpass.pColorAttachments = color_refs.data();
  subpass.pDepthStencilAttachment = &depth_ref;

  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = static_cast<uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<uint32_t>(desc.dependencies.size());
  info.pDependencies = desc.dependencies.data();
  VkRenderPass pass = VK_NULL_HANDLE;
  VK_CHECK(vkCreateRenderPass(device.get(), &info, nullptr, &pass));
  pass_ = UniqueHandle<VkRenderPass>(device.get(), pass, vkDestroyRenderPass);
  device.set_name(pass, VK_OBJECT_TYPE_RENDER_PASS, name);
}

}  // namespace vsgl
