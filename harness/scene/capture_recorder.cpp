#include "harness/scene/capture_recorder.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <glm/gtc/type_ptr.hpp>

#include "harness/core/portable_float.hpp"
#include "harness/vk/buffer.hpp"
#include "harness/vk/device.hpp"
#include "harness/core/error.hpp"
#include "harness/vk/framebuffer.hpp"
#include "harness/vk/graphics_pipeline.hpp"
#include "harness/vk/image.hpp"
#include "harness/vk/render_pass.hpp"
#include "harness/vk/texture_upload.hpp"
#include "harness/vk/unique_handle.hpp"
#include "harness/core/version.hpp"
#include "harness/capture/view_matrices.hpp"
#include "harness/vk/vk_check.hpp"
#include "kernels/include/interface/raster.h"
#include "harness/scene/scene_textures.hpp"

namespace vsgl {
namespace {

constexpr uint32_t kTargets = 5;  // position+valid, normal, diffuse, specular+roughness, pdf
constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

using gpu::RasterPush;  // kernels/include/interface/raster.h

// Mirrors MaterialBlock in kernels/include/scene_raster.glsl (std140).
struct MaterialBlock {
  glm::vec4 base_color_factor;
  glm::vec4 factors;  // metallic, perceptual roughness, normal scale, alpha cutoff
  glm::uvec4 mode;    // model (0 constants, 1 metallic-roughness, 2 vertex albedo), alpha mask, double-sided
  glm::uvec4 maps;    // base colour, metallic-roughness, normal map bound
};
static_assert(sizeof(MaterialBlock) == 64);
constexpr uint32_t kModelConstants = 0;
constexpr uint32_t kMapBindings = 3;  // base colour, metallic-roughness, normal (bindings 1..3)

VkFormat pick_depth_format(const Device& device) {
  for (VkFormat f : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_D16_UNORM}) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(device.physical(), f, &props);
    if (props.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return f;
  }
  throw DeviceError("device " + device.info().name + " supports no depth attachment format");
}

// Five colour targets cleared to zero (= invalid texel) and left for the readback copies; the
// dependencies order the pass after the previous view's copies and before this view's.
RenderPass make_render_pass(Device& device, VkFormat depth_format) {
  RenderPassDesc desc;
  desc.color_formats.assign(kTargets, kColorFormat);
  desc.color_final_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  desc.depth_format = depth_format;
  desc.dependencies.resize(2);
  auto& deps = desc.dependencies;
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
  return RenderPass(device, desc, "recorder.render_pass");
}

UniqueHandle<VkDescriptorSetLayout> make_material_set_layout(Device& device) {
  std::array<VkDescriptorSetLayoutBinding, 1 + kMapBindings> bindings{};
  bindings[0] = {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  for (uint32_t b = 1; b <= kMapBindings; ++b)
    bindings[b] = {b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = static_cast<uint32_t>(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(device.get(), &info, nullptr, &layout));
  device.set_name(layout, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, "recorder.material_set_layout");
  return UniqueHandle<VkDescriptorSetLayout>(device.get(), layout, vkDestroyDescriptorSetLayout);
}

UniqueHandle<VkPipelineLayout> make_pipeline_layout(Device& device, VkDescriptorSetLayout set_layout) {
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(RasterPush)};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device.get(), &layout_info, nullptr, &layout));
  device.set_name(layout, VK_OBJECT_TYPE_PIPELINE_LAYOUT, "recorder.pipeline_layout");
  return UniqueHandle<VkPipelineLayout>(device.get(), layout, vkDestroyPipelineLayout);
}

// cull_mode: back faces culled for one-sided surfaces (rooms face inward), none for glTF's
// double-sided materials.
GraphicsPipeline make_pipeline(Device& device, VkRenderPass pass, VkPipelineLayout layout, VkCullModeFlags cull_mode) {
  GraphicsPipelineDesc desc;
  desc.vertex_shader = "scene.vert";
  desc.fragment_shader = "capture.frag";
  desc.vertex_binding = {0, sizeof(SceneVertex), VK_VERTEX_INPUT_RATE_VERTEX};
  desc.vertex_attributes = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SceneVertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SceneVertex, normal)},
      {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SceneVertex, diffuse)},
      {3, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SceneVertex, specular)},
      {4, 0, VK_FORMAT_R32_SFLOAT, offsetof(SceneVertex, roughness)},
      {5, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(SceneVertex, uv)},
      {6, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(SceneVertex, tangent)},
  };
  desc.cull_mode = cull_mode;
  desc.front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  desc.color_attachments = kTargets;
  desc.layout = layout;
  desc.render_pass = pass;
  return GraphicsPipeline(device, desc,
                          cull_mode == VK_CULL_MODE_NONE ? "recorder.pipeline.double_sided" : "recorder.pipeline");
}

// Target t's four RGBA components go to these capture channels (-1: dropped).
constexpr int kTargetChannels[kTargets][4] = {
    {kPX, kPY, kPZ, kValid},
    {kNX, kNY, kNZ, -1},
    {kDR, kDG, kDB, -1},
    {kSR, kSG, kSB, kRoughness},
    {kPdf, -1, -1, -1},
};

// One draw: a run of triangles that share a material (and so a descriptor set and a pipeline).
struct DrawGroup {
  uint32_t first_index;
  uint32_t index_count;
  uint32_t set;          // index into SceneResources::sets (0: no material)
  bool double_sided;
};

struct Texture {
  Image2D image;
  Sampler sampler;
};

// Everything the two views draw with: vertices, indices grouped by material, the textures with
// their mip chains, one descriptor set per material.
struct SceneResources {
  Buffer vertices;
  Buffer indices;
  std::vector<DrawGroup> groups;
  std::vector<Texture> textures;  // the scene's, then one 1x1 white texture for unbound maps
  Buffer materials;               // one MaterialBlock per set, at aligned offsets
  UniqueHandle<VkDescriptorPool> pool;
  std::vector<VkDescriptorSet> sets;  // freed with the pool
};

VkSamplerAddressMode address_mode(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::kClampToEdge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case TextureWrap::kMirroredRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case TextureWrap::kRepeat: break;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkFormat texture_format(Device& device, const TextureImage& tex) {
  if (!tex.rgba8.empty()) return tex.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
  VkFormatProperties props{};
  vkGetPhysicalDeviceFormatProperties(device.physical(), VK_FORMAT_R32G32B32A32_SFLOAT, &props);
  if ((props.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) == 0)
    throw DeviceError("device " + device.info().name + " cannot filter RGBA32F textures linearly (texture '" +
                      tex.name + "'); use 8-bit textures");
  return VK_FORMAT_R32G32B32A32_SFLOAT;
}

// Uploads every level of the texture's mip chain (built on the CPU: the same levels on every
// device) and leaves it in SHADER_READ_ONLY_OPTIMAL for the fragment shader.
Texture upload_texture(Device& device, const TextureImage& tex, const std::string& name) {
  const std::vector<MipLevel> levels = build_mip_chain(tex);
  std::vector<TextureLevel> texels;
  for (const MipLevel& level : levels) {
    if (tex.rgba8.empty())
      texels.push_back({level.width, level.height, level.rgba32f.data(), level.rgba32f.size() * sizeof(float)});
    else
      texels.push_back({level.width, level.height, level.rgba8.data(), level.rgba8.size()});
  }
  Image2D image = upload_texture_levels(device, texture_format(device, tex), texels, name);

  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  info.addressModeU = address_mode(tex.wrap_u);
  info.addressModeV = address_mode(tex.wrap_v);
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  info.minLod = 0.0f;
  info.maxLod = static_cast<float>(levels.size());
  return Texture{std::move(image), Sampler(device, info, name + ".sampler")};
}

std::string material_label(const Scene& scene, uint32_t m) {
  const std::string& name = scene.materials[m].name;
  return "material " + std::to_string(m) + (name.empty() ? "" : " ('" + name + "')");
}

// Checks the scene's material and texture references (a broken reference is the importer's or a
// scene builder's bug, but it must not reach the device as an out-of-range descriptor).
void check_scene_references(const Scene& scene) {
  const auto materials = static_cast<uint32_t>(scene.materials.size());
  const auto textures = static_cast<int32_t>(scene.textures.size());
  for (std::size_t i = 0; i < scene.mesh.indices.size(); ++i) {
    const uint32_t v = scene.mesh.indices[i];
    if (v >= scene.mesh.vertices.size())
      throw InputError("scene '" + scene.name + "': index " + std::to_string(i) + " refers to vertex " +
                       std::to_string(v) + " of " + std::to_string(scene.mesh.vertices.size()));
  }
  for (const SceneVertex& v : scene.mesh.vertices)
    if (v.material != kNoMaterial && v.material >= materials)
      throw InputError("scene '" + scene.name + "': a vertex refers to material " + std::to_string(v.material) +
                       " of " + std::to_string(materials));
  for (uint32_t m = 0; m < materials; ++m) {
    const Material& mat = scene.materials[m];
    for (int32_t t : {mat.base_color_texture, mat.metallic_roughness_texture, mat.normal_texture})
      if (t < -1 || t >= textures)
        throw InputError("scene '" + scene.name + "': " + material_label(scene, m) + " refers to texture " +
                         std::to_string(t) + " of " + std::to_string(textures));
  }
}

MaterialBlock material_block(const Material& m) {
  MaterialBlock b{};
  b.base_color_factor = m.base_color_factor;
  b.factors = glm::vec4(m.metallic_factor, m.roughness_factor, m.normal_scale, m.alpha_cutoff);
  b.mode = glm::uvec4(static_cast<uint32_t>(m.model), m.alpha_mask ? 1u : 0u, m.double_sided ? 1u : 0u, 0u);
  b.maps = glm::uvec4(m.base_color_texture >= 0 ? 1u : 0u, m.metallic_roughness_texture >= 0 ? 1u : 0u,
                      m.normal_texture >= 0 ? 1u : 0u, 0u);
  return b;
}

// Triangles grouped by material, each group in the scene's order (a stable partition): a
// scene without materials is one draw of its indices exactly as given.
std::vector<uint32_t> group_by_material(const Scene& scene, std::vector<DrawGroup>& groups) {
  const SceneMesh& mesh = scene.mesh;
  const auto triangle_material = [&](std::size_t t) { return mesh.vertices[mesh.indices[3 * t]].material; };
  std::map<uint32_t, std::vector<uint32_t>> by_material;  // kNoMaterial sorts last
  for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t) by_material[triangle_material(t)].push_back(static_cast<uint32_t>(t));
  std::vector<uint32_t> indices;
  indices.reserve(mesh.indices.size());
  for (const auto& [material, triangles] : by_material) {
    const auto first = static_cast<uint32_t>(indices.size());
    for (uint32_t t : triangles) indices.insert(indices.end(), &mesh.indices[3 * t], &mesh.indices[3 * t] + 3);
    const bool has = material != kNoMaterial;
    groups.push_back(DrawGroup{first, static_cast<uint32_t>(indices.size()) - first, has ? material + 1 : 0u,
                               has && scene.materials[material].double_sided});
  }
  return indices;
}

// One descriptor set per material (set 0: the constants), each binding its MaterialBlock at
// `stride` * set and its maps, the white texture (the last) where a map is unbound.
void allocate_material_sets(Device& device, SceneResources& out, const Scene& scene, VkDescriptorSetLayout set_layout,
                            VkDeviceSize stride) {
  const auto set_count = static_cast<uint32_t>(scene.materials.size() + 1);
  const Texture& unbound = out.textures.back();
  const std::array<VkDescriptorPoolSize, 2> sizes{{
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, set_count},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, set_count * kMapBindings},
  }};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = set_count;
  pool_info.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorPool(device.get(), &pool_info, nullptr, &pool));
  device.set_name(pool, VK_OBJECT_TYPE_DESCRIPTOR_POOL, "recorder.material_pool");
  out.pool = UniqueHandle<VkDescriptorPool>(device.get(), pool, vkDestroyDescriptorPool);
  const std::vector<VkDescriptorSetLayout> layouts(set_count, set_layout);
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = set_count;
  alloc.pSetLayouts = layouts.data();
  out.sets.resize(set_count);
  VK_CHECK(vkAllocateDescriptorSets(device.get(), &alloc, out.sets.data()));

  for (uint32_t set = 0; set < set_count; ++set) {
    device.set_name(out.sets[set], VK_OBJECT_TYPE_DESCRIPTOR_SET,
                    set == 0 ? std::string("recorder.set.constants") : "recorder.set.material" + std::to_string(set - 1));
    VkDescriptorBufferInfo block{out.materials.get(), stride * set, sizeof(MaterialBlock)};
    std::array<int32_t, kMapBindings> maps{-1, -1, -1};
    if (set > 0) {
      const Material& m = scene.materials[set - 1];
      maps = {m.base_color_texture, m.metallic_roughness_texture, m.normal_texture};
    }
    std::array<VkDescriptorImageInfo, kMapBindings> images{};
    std::array<VkWriteDescriptorSet, 1 + kMapBindings> writes{};
    writes[0] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[0].dstSet = out.sets[set];
    writes[0].dstBinding = 0;
    writes[0].descriptorCount = 1;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    writes[0].pBufferInfo = &block;
    for (uint32_t k = 0; k < kMapBindings; ++k) {
      const Texture& t = maps[k] >= 0 ? out.textures[static_cast<std::size_t>(maps[k])] : unbound;
      images[k] = {t.sampler.get(), t.image.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
      writes[1 + k] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      writes[1 + k].dstSet = out.sets[set];
      writes[1 + k].dstBinding = 1 + k;
      writes[1 + k].descriptorCount = 1;
      writes[1 + k].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      writes[1 + k].pImageInfo = &images[k];
    }
    vkUpdateDescriptorSets(device.get(), static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
  }
}

SceneResources upload_scene(Device& device, const Scene& scene, VkDescriptorSetLayout set_layout) {
  const SceneMesh& mesh = scene.mesh;
  if (mesh.vertices.empty() || mesh.indices.empty())
    throw InputError("scene '" + scene.name + "' has no triangles");
  if (mesh.indices.size() % 3 != 0)
    throw InputError("scene '" + scene.name + "': " + std::to_string(mesh.indices.size()) +
                     " indices are not a whole number of triangles");
  check_scene_references(scene);

  SceneResources out;
  const std::vector<uint32_t> indices = group_by_material(scene, out.groups);
  out.vertices = Buffer(device, mesh.vertices.size() * sizeof(SceneVertex), MemoryUsage::kDeviceLocal,
                        "recorder.vertices", VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  out.indices = Buffer(device, indices.size() * sizeof(uint32_t), MemoryUsage::kDeviceLocal, "recorder.indices",
                       VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  upload(device, out.vertices, mesh.vertices.data(), out.vertices.size());
  upload(device, out.indices, indices.data(), out.indices.size());

  for (std::size_t t = 0; t < scene.textures.size(); ++t)
    out.textures.push_back(upload_texture(device, scene.textures[t], "recorder.texture" + std::to_string(t)));
  TextureImage white;
  white.name = "white";
  white.width = white.height = 1;
  white.rgba8 = {255, 255, 255, 255};
  out.textures.push_back(upload_texture(device, white, "recorder.texture.white"));

  // Set 0 draws the material-less vertices (constants); set m + 1 material m.
  const auto set_count = static_cast<uint32_t>(scene.materials.size() + 1);
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(device.physical(), &props);
  const VkDeviceSize align = std::max<VkDeviceSize>(props.limits.minUniformBufferOffsetAlignment, sizeof(MaterialBlock));
  const VkDeviceSize stride = (sizeof(MaterialBlock) + align - 1) / align * align;
  std::vector<unsigned char> blocks(static_cast<std::size_t>(stride * set_count), 0);
  for (uint32_t m = 0; m < scene.materials.size(); ++m) {
    const MaterialBlock b = material_block(scene.materials[m]);
    std::memcpy(blocks.data() + stride * (m + 1), &b, sizeof b);
  }
  out.materials = Buffer(device, blocks.size(), MemoryUsage::kDeviceLocal, "recorder.materials",
                         VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  upload(device, out.materials, blocks.data(), blocks.size());

  allocate_material_sets(device, out, scene, set_layout, stride);
  return out;
}

struct RasterState {
  UniqueHandle<VkDescriptorSetLayout> set_layout;
  UniqueHandle<VkPipelineLayout> layout;
  GraphicsPipeline one_sided;
  GraphicsPipeline double_sided;
};

RasterState make_raster_state(Device& device, VkRenderPass pass) {
  auto set_layout = make_material_set_layout(device);
  auto layout = make_pipeline_layout(device, set_layout.get());
  // Surfaces are seen from their normal side only (rooms face inward): cull what faces away,
  // except for glTF's double-sided materials.
  GraphicsPipeline one_sided = make_pipeline(device, pass, layout.get(), VK_CULL_MODE_BACK_BIT);
  GraphicsPipeline double_sided = make_pipeline(device, pass, layout.get(), VK_CULL_MODE_NONE);
  return RasterState{std::move(set_layout), std::move(layout), std::move(one_sided), std::move(double_sided)};
}

ViewImage render_view(Device& device, VkRenderPass pass, const RasterState& pipeline, VkFormat depth_format,
                      const SceneResources& mesh, ViewKind kind, uint32_t width, uint32_t height,
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

  std::vector<VkImageView> views(kTargets + 1);
  for (uint32_t t = 0; t < kTargets; ++t) views[t] = targets[t].view();
  views[kTargets] = depth.view();
  const Framebuffer framebuffer(device, pass, views, width, height, "recorder." + label + ".framebuffer");

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
        begin.framebuffer = framebuffer.get();
        begin.renderArea = {{0, 0}, {width, height}};
        begin.clearValueCount = static_cast<uint32_t>(clears.size());
        begin.pClearValues = clears.data();
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
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
        for (const DrawGroup& g : mesh.groups) {
          vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                            g.double_sided ? pipeline.double_sided.get() : pipeline.one_sided.get());
          vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout.get(), 0, 1, &mesh.sets[g.set],
                                  0, nullptr);
          vkCmdDrawIndexed(cmd, g.index_count, 1, g.first_index, 0, 0);
        }
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
  image.has_pdf = kind == ViewKind::kCamera;  // the BRSM PDF comes later (DESIGN.md §8)
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
  const RenderPass pass = make_render_pass(device_, depth_format);
  const RasterState pipeline = make_raster_state(device_, pass.get());
  const SceneResources mesh = upload_scene(device_, scene, pipeline.set_layout.get());

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

  const float cos_cone = portable::cos(glm::radians(scene.light.cone_half_angle_deg));
  RasterPush light_push{light.projection * light.view, glm::vec4(scene.light.position, 1.0f),
                        glm::vec4(glm::normalize(scene.light.direction), cos_cone),
                        glm::vec4(scene.light.intensity, rsm_texel_area(scene.light, sizes.rsm_size))};
  capture.rsm = render_view(device_, pass.get(), pipeline, depth_format, mesh, ViewKind::kLight, sizes.rsm_size,
                            sizes.rsm_size, light_push);
  return capture;
}

}  // namespace vsgl
