#pragma once
// What a compute kernel's SPIR-V declares about the resources it needs: its descriptors (set,
// binding, type, array size), its push-constant block, its shared memory and its work-group size,
// with specialization constants applied. Read from the module itself, so a pipeline's needs are
// the kernel's, not what its host believes (device_limits.hpp checks them against a device).
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

namespace vsgl {

struct ReflectedDescriptor {
  uint32_t set = 0;
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  uint32_t count = 1;
};

struct KernelInterface {
  bool compute = false;  // an entry point of the GLCompute execution model
  std::vector<ReflectedDescriptor> descriptors;
  uint32_t push_constant_bytes = 0;  // 0: no push-constant block
  uint32_t shared_memory_bytes = 0;  // Workgroup variables, laid out without padding between them
  uint32_t workgroup_size[3] = {1, 1, 1};
  // The specialization constant id each component of the work-group size takes (local_size_x_id
  // = 0 gives {0, ...}); nullopt: a literal size.
  std::array<std::optional<uint32_t>, 3> workgroup_size_spec_ids;
};

// `spec_values`: specialization constant id -> 32-bit value, as the pipeline passes them; the
// module's defaults hold for the others. Throws std::runtime_error on a module it cannot read.
KernelInterface reflect_kernel(std::span<const uint32_t> spirv, const std::map<uint32_t, uint32_t>& spec_values = {});

}  // namespace vsgl
