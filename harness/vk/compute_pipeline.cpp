#include "harness/vk/compute_pipeline.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <numeric>
#include <stdexcept>

#include "harness/vk/buffer.hpp"
#include "harness/vk/device.hpp"
#include "harness/core/error.hpp"
#include "harness/vk/shader_registry.hpp"
#include "harness/vk/spirv_reflection.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {

uint32_t float_bits(float f) {
  uint32_t u = 0;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

namespace {

// The kernel's interface with desc.constants applied; a module it cannot read names the shader.
KernelInterface reflect_desc(const ComputePipelineDesc& desc) {
  std::map<uint32_t, uint32_t> spec;
  for (const auto& c : desc.constants) spec[c.id] = c.value;
  try {
    return reflect_kernel(find_shader(desc.shader), spec);
  } catch (const std::exception& e) {
    throw std::runtime_error(desc.shader + ": " + e.what());
  }
}

PipelineNeeds needs_of(const ComputePipelineDesc& desc, const KernelInterface& k) {
  PipelineNeeds host, kernel;
  const auto add = [](PipelineNeeds& n, VkDescriptorType type, uint32_t count) {
    switch (type) {
      case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: n.storage_images += count; break;
      case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: n.sampled_images += count; break;
      case VK_DESCRIPTOR_TYPE_SAMPLER: n.samplers += count; break;
      case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER:  // counts against both limits
        n.sampled_images += count;
        n.samplers += count;
        break;
      case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: n.uniform_buffers += count; break;
      default: n.storage_buffers += count; break;
    }
  };
  host.storage_buffers = desc.storage_buffers;
  for (const auto& slot : desc.images) add(host, slot.type, slot.count);
  for (const auto& d : k.descriptors) add(kernel, d.type, d.count);
  PipelineNeeds n;
  n.name = desc.shader;
  n.storage_images = std::max(host.storage_images, kernel.storage_images);
  n.sampled_images = std::max(host.sampled_images, kernel.sampled_images);
  n.samplers = std::max(host.samplers, kernel.samplers);
  n.storage_buffers = std::max(host.storage_buffers, kernel.storage_buffers);
  n.uniform_buffers = std::max(host.uniform_buffers, kernel.uniform_buffers);
  n.descriptor_sets = 1;
  n.push_constant_bytes = std::max(desc.push_constant_bytes, k.push_constant_bytes);
  n.shared_memory_bytes = k.shared_memory_bytes;
  for (int i = 0; i < 3; ++i) n.workgroup_size[i] = k.workgroup_size[i];
  return n;
}

}  // namespace

PipelineNeeds pipeline_needs(const ComputePipelineDesc& desc) { return needs_of(desc, reflect_desc(desc)); }

ComputePipeline::ComputePipeline(Device& device, const ComputePipelineDesc& desc) : desc_(desc) {
  const KernelInterface kernel = reflect_desc(desc);
  require_fits(device.info().limits, needs_of(desc, kernel), device.info().name);
  VkDevice dev = device.get();
  const auto spirv = find_shader(desc.shader);

  // A buffer binding holds as many descriptors as the kernel declares there: an array binding
  // (the view's layers) takes one range per element.
  buffer_counts_.assign(desc.storage_buffers, 1u);
  for (const ReflectedDescriptor& d : kernel.descriptors)
    if (d.set == 0 && d.binding < desc.storage_buffers && d.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER && d.count > 1)
      buffer_counts_[d.binding] = d.count;

  std::vector<VkDescriptorSetLayoutBinding> bindings(desc.storage_buffers + desc.images.size());
  for (uint32_t i = 0; i < bindings.size(); ++i) {
    const bool buffer = i < desc.storage_buffers;
    bindings[i].binding = i;
    bindings[i].descriptorType = buffer ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER : desc.images[i - desc.storage_buffers].type;
    bindings[i].descriptorCount = buffer ? buffer_counts_[i] : desc.images[i - desc.storage_buffers].count;
    bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = static_cast<uint32_t>(bindings.size());
  set_info.pBindings = bindings.data();
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(dev, &set_info, nullptr, &set_layout));
  set_layout_ = UniqueHandle<VkDescriptorSetLayout>(dev, set_layout, vkDestroyDescriptorSetLayout);
  device.set_name(set_layout, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, desc.shader + ".set_layout");

  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, desc.push_constant_bytes};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  layout_info.pushConstantRangeCount = desc.push_constant_bytes > 0 ? 1 : 0;
  layout_info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(dev, &layout_info, nullptr, &layout));
  layout_ = UniqueHandle<VkPipelineLayout>(dev, layout, vkDestroyPipelineLayout);
  device.set_name(layout, VK_OBJECT_TYPE_PIPELINE_LAYOUT, desc.shader + ".layout");

  VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  module_info.codeSize = spirv.size() * sizeof(uint32_t);
  module_info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(dev, &module_info, nullptr, &module));
  UniqueHandle<VkShaderModule> module_owner(dev, module, vkDestroyShaderModule);
  device.set_name(module, VK_OBJECT_TYPE_SHADER_MODULE, desc.shader);

  std::vector<VkSpecializationMapEntry> entries;
  std::vector<uint32_t> values;
  for (const auto& c : desc.constants) {
    entries.push_back({c.id, static_cast<uint32_t>(values.size() * sizeof(uint32_t)), sizeof(uint32_t)});
    values.push_back(c.value);
  }
  VkSpecializationInfo spec{};
  spec.mapEntryCount = static_cast<uint32_t>(entries.size());
  spec.pMapEntries = entries.data();
  spec.dataSize = values.size() * sizeof(uint32_t);
  spec.pData = values.data();

  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = entries.empty() ? nullptr : &spec;
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VK_CHECK(vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  pipeline_ = UniqueHandle<VkPipeline>(dev, pipeline, vkDestroyPipeline);
  device.set_name(pipeline, VK_OBJECT_TYPE_PIPELINE, desc.shader);
}

std::vector<BufferBinding> buffer_bindings(std::initializer_list<std::vector<BufferBinding>> groups) {
  std::vector<BufferBinding> out;
  for (const auto& g : groups) out.insert(out.end(), g.begin(), g.end());
  return out;
}

BindingSet::BindingSet(Device& device, const ComputePipeline& pipeline, std::initializer_list<BufferBinding> buffers,
                       const std::string& name)
    : BindingSet(device, pipeline, std::vector<BufferBinding>(buffers), name) {}

BindingSet::BindingSet(Device& device, const ComputePipeline& pipeline, const std::vector<BufferBinding>& buffers,
                       const std::string& name)
    : BindingSet(device, pipeline, buffers, {}, name) {}

BindingSet::BindingSet(Device& device, const ComputePipeline& pipeline, const std::vector<BufferBinding>& buffers,
                       const std::vector<ImageBinding>& images, const std::string& name) {
  VkDevice dev = device.get();
  const std::vector<uint32_t>& counts = pipeline.buffer_counts();
  const auto n = static_cast<uint32_t>(buffers.size());
  if (n != std::accumulate(counts.begin(), counts.end(), 0u))
    throw std::logic_error("binding set '" + name + "' has " + std::to_string(n) + " buffers, " +
                           pipeline.desc().shader + " takes " +
                           std::to_string(std::accumulate(counts.begin(), counts.end(), 0u)) + " in " +
                           std::to_string(counts.size()) + " bindings");
  const auto& slots = pipeline.desc().images;
  if (images.size() != slots.size())
    throw std::logic_error("binding set '" + name + "' has " + std::to_string(images.size()) + " image bindings, " +
                           pipeline.desc().shader + " takes " + std::to_string(slots.size()));
  std::vector<VkDescriptorPoolSize> sizes{{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, n == 0 ? 1 : n}};
  for (std::size_t k = 0; k < slots.size(); ++k) {
    if (images[k].views.size() != slots[k].count)
      throw std::logic_error("binding set '" + name + "': image binding " + std::to_string(k) + " has " +
                             std::to_string(images[k].views.size()) + " views, expected " +
                             std::to_string(slots[k].count));
    sizes.push_back({slots[k].type, slots[k].count});
  }
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorPool(dev, &pool_info, nullptr, &pool));
  pool_ = UniqueHandle<VkDescriptorPool>(dev, pool, vkDestroyDescriptorPool);
  device.set_name(pool, VK_OBJECT_TYPE_DESCRIPTOR_POOL, name + ".pool");

  VkDescriptorSetLayout layout = pipeline.set_layout();
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout;
  VK_CHECK(vkAllocateDescriptorSets(dev, &alloc, &set_));
  device.set_name(set_, VK_OBJECT_TYPE_DESCRIPTOR_SET, name);

  std::vector<VkDescriptorBufferInfo> infos(n);
  std::vector<VkWriteDescriptorSet> writes(counts.size());
  const uint32_t max_range = device.info().limits.storage_buffer_range;
  for (uint32_t i = 0; i < n; ++i) {
    const VkDeviceSize range = buffers[i].range == VK_WHOLE_SIZE ? buffers[i].buffer->size() - buffers[i].offset
                                                                  : buffers[i].range;
    if (range > max_range)
      throw DeviceLimitError(device.info().name + " cannot bind " + std::to_string(range) +
                             " bytes of a storage buffer to '" + name + "': the device allows " +
                             std::to_string(max_range) + " (maxStorageBufferRange)");
    infos[i] = {buffers[i].buffer->get(), buffers[i].offset, buffers[i].range};
  }
  for (uint32_t b = 0, first = 0; b < counts.size(); first += counts[b++]) {
    writes[b] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[b].dstSet = set_;
    writes[b].dstBinding = b;
    writes[b].descriptorCount = counts[b];
    writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[b].pBufferInfo = &infos[first];
  }
  std::vector<std::vector<VkDescriptorImageInfo>> image_infos(slots.size());
  for (std::size_t k = 0; k < slots.size(); ++k) {
    for (VkImageView v : images[k].views) image_infos[k].push_back({images[k].sampler, v, VK_IMAGE_LAYOUT_GENERAL});
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set_;
    w.dstBinding = static_cast<uint32_t>(counts.size() + k);
    w.descriptorCount = slots[k].count;
    w.descriptorType = slots[k].type;
    w.pImageInfo = image_infos[k].data();
    writes.push_back(w);
  }
  if (!writes.empty()) vkUpdateDescriptorSets(dev, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace vsgl
