#include "harness/vk/device_limits.hpp"

#include <nlohmann/json.hpp>

#include "harness/core/error.hpp"

namespace vsgl {

DeviceLimits read_device_limits(const VkPhysicalDeviceProperties& props, uint64_t max_allocation,
                                uint32_t subgroup_size, VkFormatFeatureFlags rgba32f_features) {
  const VkPhysicalDeviceLimits& l = props.limits;
  DeviceLimits d;
  d.per_stage_storage_images = l.maxPerStageDescriptorStorageImages;
  d.per_stage_sampled_images = l.maxPerStageDescriptorSampledImages;
  d.per_stage_samplers = l.maxPerStageDescriptorSamplers;
  d.per_stage_storage_buffers = l.maxPerStageDescriptorStorageBuffers;
  d.per_stage_uniform_buffers = l.maxPerStageDescriptorUniformBuffers;
  d.per_stage_resources = l.maxPerStageResources;
  d.set_storage_images = l.maxDescriptorSetStorageImages;
  d.set_sampled_images = l.maxDescriptorSetSampledImages;
  d.set_samplers = l.maxDescriptorSetSamplers;
  d.set_storage_buffers = l.maxDescriptorSetStorageBuffers;
  d.set_uniform_buffers = l.maxDescriptorSetUniformBuffers;
  d.bound_descriptor_sets = l.maxBoundDescriptorSets;
  d.push_constants_size = l.maxPushConstantsSize;
  d.compute_shared_memory = l.maxComputeSharedMemorySize;
  for (int k = 0; k < 3; ++k) {
    d.workgroup_size[k] = l.maxComputeWorkGroupSize[k];
    d.workgroup_count[k] = l.maxComputeWorkGroupCount[k];
  }
  d.workgroup_invocations = l.maxComputeWorkGroupInvocations;
  d.image_dimension_2d = l.maxImageDimension2D;
  d.image_array_layers = l.maxImageArrayLayers;
  d.storage_buffer_range = l.maxStorageBufferRange;
  d.storage_buffer_offset_alignment = l.minStorageBufferOffsetAlignment;
  d.max_memory_allocation_size = max_allocation;
  d.subgroup_size = subgroup_size;
  const auto has = [&](VkFormatFeatureFlags bit) { return (rgba32f_features & bit) != 0; };
  d.rgba32f_optimal_tiling = {has(VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT),
                              has(VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT),
                              has(VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT), has(VK_FORMAT_FEATURE_BLIT_SRC_BIT),
                              has(VK_FORMAT_FEATURE_BLIT_DST_BIT)};
  return d;
}

nlohmann::ordered_json to_json(const PipelineNeeds& n) {
  return nlohmann::ordered_json{{"kernel", n.name},
                                {"storage_images", n.storage_images},
                                {"sampled_images", n.sampled_images},
                                {"samplers", n.samplers},
                                {"storage_buffers", n.storage_buffers},
                                {"uniform_buffers", n.uniform_buffers},
                                {"push_constant_bytes", n.push_constant_bytes},
                                {"shared_memory_bytes", n.shared_memory_bytes},
                                {"workgroup_size", {n.workgroup_size[0], n.workgroup_size[1], n.workgroup_size[2]}}};
}

std::string LimitShortfall::message(const std::string& what) const {
  return what + " needs " + std::to_string(needed) + " where the device allows " + std::to_string(value) + " (" +
         limit + ")";
}

std::vector<LimitShortfall> shortfalls(const DeviceLimits& d, const PipelineNeeds& n) {
  std::vector<LimitShortfall> out;
  auto check = [&](const char* limit, uint64_t value, uint64_t needed) {
    if (needed > value) out.push_back({limit, value, needed});
  };
  // One compute stage per pipeline, so its per-stage and per-layout counts are the same numbers.
  check("maxPerStageDescriptorStorageImages", d.per_stage_storage_images, n.storage_images);
  check("maxPerStageDescriptorSampledImages", d.per_stage_sampled_images, n.sampled_images);
  check("maxPerStageDescriptorSamplers", d.per_stage_samplers, n.samplers);
  check("maxPerStageDescriptorStorageBuffers", d.per_stage_storage_buffers, n.storage_buffers);
  check("maxPerStageDescriptorUniformBuffers", d.per_stage_uniform_buffers, n.uniform_buffers);
  check("maxPerStageResources", d.per_stage_resources, n.resources());
  check("maxDescriptorSetStorageImages", d.set_storage_images, n.storage_images);
  check("maxDescriptorSetSampledImages", d.set_sampled_images, n.sampled_images);
  check("maxDescriptorSetSamplers", d.set_samplers, n.samplers);
  check("maxDescriptorSetStorageBuffers", d.set_storage_buffers, n.storage_buffers);
  check("maxDescriptorSetUniformBuffers", d.set_uniform_buffers, n.uniform_buffers);
  check("maxBoundDescriptorSets", d.bound_descriptor_sets, n.descriptor_sets);
  check("maxPushConstantsSize", d.push_constants_size, n.push_constant_bytes);
  check("maxComputeSharedMemorySize", d.compute_shared_memory, n.shared_memory_bytes);
  check("maxComputeWorkGroupSize[0]", d.workgroup_size[0], n.workgroup_size[0]);
  check("maxComputeWorkGroupSize[1]", d.workgroup_size[1], n.workgroup_size[1]);
  check("maxComputeWorkGroupSize[2]", d.workgroup_size[2], n.workgroup_size[2]);
  check("maxComputeWorkGroupInvocations", d.workgroup_invocations, n.invocations());
  return out;
}

std::string does_not_fit_reason(const DeviceLimits& limits, const PipelineNeeds& needs) {
  const auto s = shortfalls(limits, needs);
  return s.empty() ? std::string() : s.front().message(needs.name);
}

void require_fits(const DeviceLimits& limits, const PipelineNeeds& needs, const std::string& device_name) {
  const std::string why = does_not_fit_reason(limits, needs);
  if (!why.empty()) throw DeviceError(device_name + " cannot run " + needs.name + ": " + why);
}

}  // namespace vsgl
