#pragma once
// The device limits (core/device_limits.hpp) as the driver reports them, and the check of one
// pipeline's needs against them. Every pipeline is checked BEFORE it is created (DESIGN.md §9: a device that
// enforces a limit the pipeline exceeds gives undefined behaviour, not an error), so a need that
// does not fit is a DeviceError naming the limit, its value and what was needed.
#include <vulkan/vulkan.h>

#include "harness/core/device_limits.hpp"

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace vsgl {

DeviceLimits read_device_limits(const VkPhysicalDeviceProperties& props, uint64_t max_allocation,
                                uint32_t subgroup_size, VkFormatFeatureFlags rgba32f_features);

// What one compute pipeline needs: its set layout's descriptors by type (a combined image sampler
// counts as one sampled image and one sampler, as the per-stage limits count it), its push
// constants, and from its SPIR-V the shared memory and the work-group size (specialized).
struct PipelineNeeds {
  std::string name;  // the kernel
  uint32_t storage_images = 0;
  uint32_t sampled_images = 0;
  uint32_t samplers = 0;
  uint32_t storage_buffers = 0;
  uint32_t uniform_buffers = 0;
  uint32_t descriptor_sets = 0;
  uint32_t push_constant_bytes = 0;
  uint32_t shared_memory_bytes = 0;
  uint32_t workgroup_size[3] = {1, 1, 1};
  uint32_t resources() const { return storage_images + sampled_images + storage_buffers + uniform_buffers; }
  uint32_t invocations() const { return workgroup_size[0] * workgroup_size[1] * workgroup_size[2]; }
};
nlohmann::ordered_json to_json(const PipelineNeeds& needs);

// One limit a need exceeds, e.g. {"maxPerStageDescriptorStorageImages", 16, 17}.
struct LimitShortfall {
  std::string limit;  // the Vulkan name of the limit
  uint64_t value = 0;
  uint64_t needed = 0;
  std::string message(const std::string& what) const;  // "<what> needs 17 ... the device allows 16 (limit)"
};

// Every limit `needs` exceeds; empty when it fits.
std::vector<LimitShortfall> shortfalls(const DeviceLimits& limits, const PipelineNeeds& needs);
// The first shortfall as one sentence, empty when it fits.
std::string does_not_fit_reason(const DeviceLimits& limits, const PipelineNeeds& needs);
// Throws DeviceError (exit 4) with does_not_fit_reason when `needs` does not fit.
void require_fits(const DeviceLimits& limits, const PipelineNeeds& needs, const std::string& device_name);

}  // namespace vsgl
