#pragma once
// The device limits vsgl-bench's kernels and captures depend on, as plain data: the vk layer reads
// them from the driver (vk/device_limits.hpp, which also checks a pipeline's needs against them)
// and every document that records a device writes and reads them here, by their Vulkan names
// (DESIGN.md §10: the `limits` object of devices.json, and of the device in tables and sweeps).
#include <array>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace vsgl {

class JsonReader;  // core/json_reader.hpp

// VK_FORMAT_R32G32B32A32_SFLOAT's optimal tiling features the FIS paths use.
struct Rgba32fFeatures {
  bool sampled_image = false;
  bool sampled_image_filter_linear = false;
  bool storage_image = false;
  bool blit_src = false;
  bool blit_dst = false;
};

struct DeviceLimits {
  // Descriptors one compute stage may access, by type (VkPhysicalDeviceLimits::maxPerStage*).
  uint32_t per_stage_storage_images = 0;
  uint32_t per_stage_sampled_images = 0;
  uint32_t per_stage_samplers = 0;
  uint32_t per_stage_storage_buffers = 0;
  uint32_t per_stage_uniform_buffers = 0;
  uint32_t per_stage_resources = 0;
  // ... and one pipeline layout's sets together (maxDescriptorSet*).
  uint32_t set_storage_images = 0;
  uint32_t set_sampled_images = 0;
  uint32_t set_samplers = 0;
  uint32_t set_storage_buffers = 0;
  uint32_t set_uniform_buffers = 0;
  uint32_t bound_descriptor_sets = 0;
  uint32_t push_constants_size = 0;
  uint32_t compute_shared_memory = 0;
  std::array<uint32_t, 3> workgroup_size{};
  uint32_t workgroup_invocations = 0;
  std::array<uint32_t, 3> workgroup_count{};
  uint32_t image_dimension_2d = 0;
  uint32_t image_array_layers = 0;
  uint32_t storage_buffer_range = 0;
  // minStorageBufferOffsetAlignment: how the run lays out its buffers, not a limit a document
  // reports, so no file holds it and a limits object read back leaves it at 1.
  uint64_t storage_buffer_offset_alignment = 1;
  uint64_t max_memory_allocation_size = 0;  // VkPhysicalDeviceMaintenance3Properties (Vulkan 1.1)
  uint32_t subgroup_size = 0;
  Rgba32fFeatures rgba32f_optimal_tiling;
};

// The `limits` object: every member above but the offset alignment, by its Vulkan name, the keys
// sorted (core/sorted_json.hpp).
nlohmann::ordered_json to_json(const DeviceLimits& limits);
// Reads what to_json writes at `path`; refuses a missing, mistyped or unknown member (InputError
// naming its pointer).
DeviceLimits device_limits_from_json(const JsonReader& reader, const nlohmann::ordered_json& limits,
                                     const std::string& path);

}  // namespace vsgl
