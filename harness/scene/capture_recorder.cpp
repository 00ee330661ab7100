#include "harness/scene/capture_recorder.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>

#include "harness/vk/buffer.hpp"
#include "harness/vk/device.hpp"
#include "harness/core/error.hpp"
#include "harness/vk/image.hpp"
#include "harness/vk/shader_registry.hpp"
#include "harness/vk/unique_handle.hpp"
#include "harness/core/version.hpp"
#include "harness/capture/view_matrices.hpp"
#include "harness/vk/vk_check.hpp"
#include "kernels/include/interface/raster.h"

namespace vsgl {
namespace {

constexpr uint32_t kTargets = 5;  // position+valid, normal, diffuse, specular+roughness, pdf
constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

using gpu::RasterPush;  // kernels/include/interface/raster.h

VkFormat pick_depth_format(const Device& device) {
  for (VkFormat f : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_D16_UNORM}) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(device.physical(), f, &props);
    if (props.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return f;
  }
  throw DeviceError("device " + device.info().name + " supports no depth attachment format");
}

UniqueHandle<VkShaderModule> make_module(Device& device, const char* name) {
  const auto spirv = find_shader(name);
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size() * sizeof(uint32_t);
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device.get(), &info, nullptr, &module));
  device.set_name(module, VK_OBJECT_TYPE_SHADER_MODULE, name);
  return UniqueHandle<VkShaderModule>(device.get(), module, vkDestroyShaderModule);
}

UniqueHandle<VkRenderPass> make_render_pass(Device& device, VkFormat depth_format) {
  std::array<VkAttachmentDescription, kTargets + 1> attachments{};
  for (uint32_t i = 0; i < kTargets; ++i) {
    attachments[i].format = kColorFormat;
    attachments[i].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;  // zero = invalid texel
    attachments[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[i].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[i].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[i].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[i].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  }
  auto& depth = attachments[kTargets];
  depth.format = depth_format;
  depth.samples = VK_SAMPLE_COUNT_1_BIT;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  depth.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;

  std::array<VkAttachmentReference, kTargets> color_refs{};
  for (uint32_t i = 0; i < kTargets; ++i) color_refs[i] = {i, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth_ref{kTargets, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = kTargets;
  subpass.pColorAttachments = color_refs.data();
  subpass.pDepthStencilAttachment = &depth_ref;

  std::array<VkSubpassDependency, 2> deps{};
  deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  deps[0].dstSubpass = 0;
  deps[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                         VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  deps[0].srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                          VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                         VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  deps[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                          VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  deps[1].srcSubpass = 0;
  deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  deps[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;

  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = static_cast<uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<uint32_t>(deps.size());
  info.pDependencies = deps.data();
  VkRenderPass pass = VK_NULL_HANDLE;
  VK_CHECK(vkCreateRenderPass(device.get(), &info, nullptr, &pass));
  device.set_name(pass, VK_OBJECT_TYPE_RENDER_PASS, "recorder.render_pass");
  return UniqueHandle<VkRenderPass>(device.get(), pass, vkDestroyRenderPass);
}

struct RasterPipeline {
  UniqueHandle<VkPipelineLayout> layout;
  UniqueHandle<VkPipeline> pipeline;
};

RasterPipeline make_pipeline(Device& device, VkRenderPass pass) {
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(RasterPush)};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device.get(), &layout_info, nullptr, &layout));
  RasterPipeline out;
  out.layout = UniqueHandle<VkPipelineLayout>(device.get(), layout, vkDestroyPipelineLayout);

  auto vert = make_module(device, "scene.vert");
  auto frag = make_module(device, "capture.frag");
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vert.get();
  stages[0].pName = "main";
  stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = frag.get();
  stages[1].pName = "main";

  VkVertexInputBindingDescription binding{0, sizeof(SceneVertex), VK_VERTEX_INPUT_RATE_VERTEX};
  const std::array<VkVertexInputAttributeDescription, 5> attrs{{
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SceneVertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SceneVertex, normal)},
      {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SceneVertex, diffuse)},
      {3, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SceneVertex, specular)},
      {4, 0, VK_FORMAT_R32_SFLOAT, offsetof(SceneVertex, roughness)},
  }};
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex_input.vertexBindingDescriptionCount = 1;
  vertex_input.pVertexBindingDescriptions = &binding;
  vertex_input.vertexAttributeDescriptionCount = static_cast<uint32_t>(attrs.size());
  vertex_input.pVertexAttributeDescriptions = attrs.data();

  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  // Surfaces are seen from their normal side only (rooms face inward): cull what faces away.
  raster.cullMode = VK_CULL_MODE_BACK_BIT;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;
  std::array<VkPipelineColorBlendAttachmentState, kTargets> blend{};
  for (auto& b : blend)
    b.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                       VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo color{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  color.attachmentCount = kTargets;
  color.pAttachments = blend.data();
  const std::array<VkDynamicState, 2> dynamic_states{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = static_cast<uint32_t>(dynamic_states.size());
  dynamic.pDynamicStates = dynamic_states.data();

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = static_cast<uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &color;
  info.pDynamicState = &dynamic;
  info.layout = layout;
  info.renderPass = pass;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VK_CHECK(vkCreateGraphicsPipelines(device.get(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  device.set_name(pipeline, VK_OBJECT_TYPE_PIPELINE, "recorder.pipeline");
  out.pipeline = UniqueHandle<VkPipeline>(device.get(), pipeline, vkDestroyPipeline);
  return out;
}

// Target t's four RGBA components go to these capture channels (-1: dropped).
constexpr int kTargetChannels[kTargets][4] = {
    {kPX, kPY, kPZ, kValid},
    {kNX, kNY, kNZ, -1},
    {kDR, kDG, kDB, -1},
    {kSR, kSG, kSB, kRoughness},
    {kPdf, -1, -1, -1},
};

struct MeshBuffers {
  Buffer vertices;
  Buffer indices;
  uint32_t index_count;
};

MeshBuffers upload_mesh(Device& device, const SceneMesh& mesh) {
  if (mesh.vertices.empty() || mesh.indices.empty()) throw InputError("scene mesh is empty");
  MeshBuffers out{Buffer(device, mesh.vertices.size() * sizeof(SceneVertex), MemoryUsage::kDeviceLocal,
                         "recorder.vertices", VK_BUFFER_USAGE_VERTEX_BUFFER_BIT),
                  Buffer(device, mesh.indices.size() * sizeof(uint32_t), MemoryUsage::kDeviceLocal,
                         "recorder.indices", VK_BUFFER_USAGE_INDEX_BUFFER_BIT),
                  static_cast<uint32_t>(mesh.indices.size())};
  upload(device, out.vertices, mesh.vertices.data(), out.vertices.size());
  upload(device, out.indices, mesh.indices.data(), out.indices.size());
  return out;
}

ViewImage render_view(Device& device, VkRenderPass pass, const RasterPipeline& pipeline, VkFormat depth_format,
                      const MeshBuffers& mesh, ViewKind kind, uint32_t width, uint32_t height,
                      const RasterPush& push) {
  const std::string label = view_label(kind);
  std::vector<Image2D> targets;
  targets.reserve(kTargets);
  for (uint32_t t = 0; t < kTargets; ++t)
    targets.emplace_back(device, width, height, kColorFormat,
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                         VK_IMAGE_ASPECT_COLOR_BIT, "recorder." + label + ".target" + std::to_string(t));
  Image2D depth(device, width, height, depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                VK_IMAGE_ASPECT_DEPTH_BIT, "recorder." + label + ".depth");

  std::array<VkImageView, kTargets + 1> views{};
  for (uint32_t t = 0; t < kTargets; ++t) views[t] = targets[t].view();
  views[kTargets] = depth.view();
  VkFramebufferCreateInfo fb_info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fb_info.renderPass = pass;
  fb_info.attachmentCount = static_cast<uint32_t>(views.size());
  fb_info.pAttachments = views.data();
  fb_info.width = width;
  fb_info.height = height;
  fb_info.layers = 1;
  VkFramebuffer fb = VK_NULL_HANDLE;
  VK_CHECK(vkCreateFramebuffer(device.get(), &fb_info, nullptr, &fb));
  UniqueHandle<VkFramebuffer> framebuffer(device.get(), fb, vkDestroyFramebuffer);

  const VkDeviceSize target_bytes = VkDeviceSize{width} * height * 4 * sizeof(float);
  std::vector<Buffer> readback;
  readback.reserve(kTargets);
  for (uint32_t t = 0; t < kTargets; ++t)
    readback.emplace_back(device, target_bytes, MemoryUsage::kReadback,
                          "recorder." + label + ".readback" + std::to_string(t));

  device.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        std::array<VkClearValue, kTargets + 1> clears{};
        clears[kTargets].depthStencil = {1.0f, 0};
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = pass;
        begin.framebuffer = fb;
        begin.renderArea = {{0, 0}, {width, height}};
        begin.clearValueCount = static_cast<uint32_t>(clears.size());
        begin.pClearValues = clears.data();
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline.get());
        VkViewport vp{0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height), 0.0f, 1.0f};
        VkRect2D scissor{{0, 0}, {width, height}};
        vkCmdSetViewport(cmd, 0, 1, &vp);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdPushConstants(cmd, pipeline.layout.get(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof push, &push);
        VkDeviceSize offset = 0;
        VkBuffer vb = mesh.vertices.get();
        vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
        vkCmdBindIndexBuffer(cmd, mesh.indices.get(), 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd, mesh.index_count, 1, 0, 0, 0);
        vkCmdEndRenderPass(cmd);
        for (uint32_t t = 0; t < kTargets; ++t) {
          VkBufferImageCopy region{};
          region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
          region.imageExtent = {width, height, 1};
          vkCmdCopyImageToBuffer(cmd, targets[t].get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback[t].get(), 1,
                                 &region);
        }
        VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0,
                             nullptr, 0, nullptr);
      },
      "record " + label);

  ViewImage image;
  image.resize(kind, width, height);
  image.has_pdf = kind == ViewKind::kCamera;  // the BRSM PDF comes later (SPEC §8)
  const std::size_t n = image.texels();
  for (uint32_t t = 0; t < kTargets; ++t) {
    const auto* rgba = static_cast<const float*>(readback[t].mapped());
    for (int c = 0; c < 4; ++c) {
      const int channel = kTargetChannels[t][c];
      if (channel < 0) continue;
      float* plane = image.planes[static_cast<std::size_t>(channel)].data();
      for (std::size_t i = 0; i < n; ++i) plane[i] = rgba[i * 4 + static_cast<std::size_t>(c)];
    }
  }
  return image;
}

void check_size(const char* what, uint32_t w, uint32_t h, const DeviceInfo& info) {
  if (w == 0 || h == 0) throw InputError(std::string(what) + " size must be positive");
  if (w > 16384 || h > 16384)
    throw InputError(std::string(what) + " size " + std::to_string(w) + "x" + std::to_string(h) +
                     " exceeds 16384 (device " + info.name + ")");
}

}  // namespace

CaptureRecorder::CaptureRecorder(Device& device) : device_(device) {
  if (!device.info().graphics)
    throw DeviceError("device " + device.info().name + " has no graphics queue: the recorder rasterizes "
                      "captures; record them on another device (captures are portable)");
}

Capture CaptureRecorder::record(const Scene& scene, const RecordSizes& sizes, uint32_t frame, uint32_t frames) {
  check_size("G-buffer", sizes.gbuffer_width, sizes.gbuffer_height, device_.info());
  check_size("RSM", sizes.rsm_size, sizes.rsm_size, device_.info());
  const VkFormat depth_format = pick_depth_format(device_);
  auto pass = make_render_pass(device_, depth_format);
  const RasterPipeline pipeline = make_pipeline(device_, pass.get());
  const MeshBuffers mesh = upload_mesh(device_, scene.mesh);

  Capture capture;
  CaptureMeta& meta = capture.meta;
  meta.scene = scene.name;
  meta.frame = frame;
  meta.frames = frames;
  meta.camera = scene.camera;
  meta.light = scene.light;
  meta.device = device_.info().name;
  meta.tool_version = kVersionString;

  const ViewMatrices cam = camera_matrices(
      scene.camera, static_cast<float>(sizes.gbuffer_width) / static_cast<float>(sizes.gbuffer_height));
  meta.camera_view = cam.view;
  meta.camera_projection = cam.projection;
  const ViewMatrices light = light_matrices(scene.light);
  meta.light_view = light.view;
  meta.light_projection = light.projection;

  RasterPush camera_push{cam.projection * cam.view, glm::vec4(scene.camera.position, 0.0f), glm::vec4(0.0f),
                         glm::vec4(0.0f)};
  capture.gbuffer = render_view(device_, pass.get(), pipeline, depth_format, mesh, ViewKind::kCamera,
                                sizes.gbuffer_width, sizes.gbuffer_height, camera_push);

  const float cos_cone = std::cos(glm::radians(scene.light.cone_half_angle_deg));
  RasterPush light_push{light.projection * light.view, glm::vec4(scene.light.position, 1.0f),
                        glm::vec4(glm::normalize(scene.light.direction), cos_cone),
                        glm::vec4(scene.light.intensity, rsm_texel_area(scene.light, sizes.rsm_size))};
  capture.rsm = render_view(device_, pass.get(), pipeline, depth_format, mesh, ViewKind::kLight, sizes.rsm_size,
                            sizes.rsm_size, light_push);
  return capture;
}

}  // namespace vsgl
