#pragma once
// A graphics pipeline built from two embedded shaders: one interleaved vertex buffer, triangle
// lists, filled polygons, one sample, depth test and write (LESS), every colour attachment
// written without blending, viewport and scissor dynamic.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "harness/vk/unique_handle.hpp"

namespace vsgl {

class Device;

struct GraphicsPipelineDesc {
  std::string vertex_shader;    // embedded names, e.g. "scene.vert"
  std::string fragment_shader;
  VkVertexInputBindingDescription vertex_binding{};
  std::vector<VkVertexInputAttributeDescription> vertex_attributes;
  VkCullModeFlags cull_mode = VK_CULL_MODE_BACK_BIT;
  VkFrontFace front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  uint32_t color_attachments = 1;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;  // subpass 0
};

class GraphicsPipeline {
 public:
  GraphicsPipeline(Device& device, const GraphicsPipelineDesc& desc, const std::string& name);
  VkPipeline get() const { return pipeline_.get(); }

 private:
  UniqueHandle<VkPipeline> pipeline_;
};

}  // namespace vsgl
