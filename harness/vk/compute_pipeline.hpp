#pragma once
// A compute pipeline built from an embedded kernel: storage buffers at bindings 0..n-1 of set 0,
// an optional push-constant block, and specialization constants (local sizes, iteration counts).
#include <vulkan/vulkan.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "harness/vk/device_limits.hpp"
#include "harness/vk/unique_handle.hpp"

namespace vsgl {

class Buffer;
class Device;

struct SpecializationConstant {
  uint32_t id;
  uint32_t value;  // 32-bit int/uint/bool; floats via float_bits()
};
uint32_t float_bits(float f);

// The work-group size of a kernel declared `layout(local_size_x_id = 0) in;` (1D) or
// `layout(local_size_x_id = 0, local_size_y_id = 1) in;` (2D); a 1D kernel may give id 1 to
// another constant.
inline std::vector<SpecializationConstant> work_group_size_1d(uint32_t x) { return {{0, x}}; }
inline std::vector<SpecializationConstant> work_group_size_2d(uint32_t x, uint32_t y) { return {{0, x}, {1, y}}; }

// An image binding after the storage buffers: a storage image or a combined image sampler,
// possibly an array of `count` descriptors.
struct ImageSlot {
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  uint32_t count = 1;
};

struct ComputePipelineDesc {
  std::string shader;             // embedded name, e.g. "fis_mip_level.comp"
  uint32_t storage_buffers = 0;   // bindings 0..n-1
  uint32_t push_constant_bytes = 0;
  std::vector<SpecializationConstant> constants;
  std::vector<ImageSlot> images;  // bindings n, n+1, ...
};

// What the pipeline of `desc` needs: its set layout's descriptors (the larger of what the host
// declares and what the kernel's SPIR-V declares, per type), push constants, and from the SPIR-V
// with `desc.constants` applied its shared memory and work-group size. Needs no device.
PipelineNeeds pipeline_needs(const ComputePipelineDesc& desc);

class ComputePipeline {
 public:
  // Checks pipeline_needs(desc) against the device's limits first: DeviceError (exit 4) naming the
  // limit, its value and the need when it does not fit; nothing is created then.
  ComputePipeline(Device& device, const ComputePipelineDesc& desc);
  ComputePipeline(ComputePipeline&&) noexcept = default;
  ComputePipeline& operator=(ComputePipeline&&) noexcept = default;

  VkPipeline get() const { return pipeline_.get(); }
  VkPipelineLayout layout() const { return layout_.get(); }
  VkDescriptorSetLayout set_layout() const { return set_layout_.get(); }
  const ComputePipelineDesc& desc() const { return desc_; }
  // Descriptors per buffer binding: 1, or the length of an array the kernel declares there.
  const std::vector<uint32_t>& buffer_counts() const { return buffer_counts_; }

 private:
  ComputePipelineDesc desc_;
  std::vector<uint32_t> buffer_counts_;
  UniqueHandle<VkDescriptorSetLayout> set_layout_;
  UniqueHandle<VkPipelineLayout> layout_;
  UniqueHandle<VkPipeline> pipeline_;
};

// A range of a buffer bound to one binding (whole buffer by default).
struct BufferBinding {
  const Buffer* buffer;
  VkDeviceSize offset = 0;
  VkDeviceSize range = VK_WHOLE_SIZE;
  BufferBinding(const Buffer& b) : buffer(&b) {}  // NOLINT(google-explicit-constructor): reads naturally
  BufferBinding(const Buffer& b, VkDeviceSize off, VkDeviceSize r) : buffer(&b), offset(off), range(r) {}
};

// Buffer bindings in binding order from one group per binding: a buffer, or the elements of an
// array binding (DeviceView::layers()).
std::vector<BufferBinding> buffer_bindings(std::initializer_list<std::vector<BufferBinding>> groups);

// The views (and, for a combined image sampler, the sampler) of one ImageSlot; images stay in
// VK_IMAGE_LAYOUT_GENERAL.
struct ImageBinding {
  std::vector<VkImageView> views;
  VkSampler sampler = VK_NULL_HANDLE;
};

// One descriptor set (with its own small pool) binding buffers, then images, to a pipeline's
// bindings in order; an array buffer binding of c descriptors takes the next c buffers.
class BindingSet {
 public:
  BindingSet(Device& device, const ComputePipeline& pipeline, std::initializer_list<BufferBinding> buffers,
             const std::string& name);
  BindingSet(Device& device, const ComputePipeline& pipeline, const std::vector<BufferBinding>& buffers,
             const std::string& name);
  BindingSet(Device& device, const ComputePipeline& pipeline, const std::vector<BufferBinding>& buffers,
             const std::vector<ImageBinding>& images, const std::string& name);
  BindingSet(BindingSet&&) noexcept = default;
  BindingSet& operator=(BindingSet&&) noexcept = default;
  VkDescriptorSet get() const { return set_; }

 private:
  UniqueHandle<VkDescriptorPool> pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace vsgl
