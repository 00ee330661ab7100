#include "harness/vk/portability_baselines.hpp"

namespace vsgl {

const DeviceLimits& vulkan12_required_limits() {
  static const DeviceLimits l = [] {
    DeviceLimits d;
    d.per_stage_storage_images = 4;
    d.per_stage_sampled_images = 16;
    d.per_stage_samplers = 16;
    d.per_stage_storage_buffers = 4;
    d.per_stage_uniform_buffers = 12;
    d.per_stage_resources = 128;
    d.set_storage_images = 24;
    d.set_sampled_images = 96;
    d.set_samplers = 96;
    d.set_storage_buffers = 24;
    d.set_uniform_buffers = 72;
    d.bound_descriptor_sets = 4;
    d.push_constants_size = 128;
    d.compute_shared_memory = 16384;
    d.workgroup_size[0] = 128;
    d.workgroup_size[1] = 128;
    d.workgroup_size[2] = 64;
    d.workgroup_invocations = 128;
    d.workgroup_count[0] = d.workgroup_count[1] = d.workgroup_count[2] = 65535;
    d.image_dimension_2d = 4096;
    d.image_array_layers = 256;
    d.storage_buffer_range = 1u << 27;
    d.max_memory_allocation_size = 1ull << 30;
    return d;
  }();
  return l;
}

const DeviceLimits& desktop_baseline_2023_limits() {
  static const DeviceLimits l = [] {
    DeviceLimits d;
    d.per_stage_storage_images = 8;
    d.per_stage_sampled_images = 128;
    d.per_stage_samplers = 16;
    d.per_stage_storage_buffers = 31;
    d.per_stage_uniform_buffers = 15;
    d.per_stage_resources = 159;
    d.set_storage_images = 40;
    d.set_sampled_images = 640;
    d.set_samplers = 80;
    d.set_storage_buffers = 155;
    d.set_uniform_buffers = 90;
    d.bound_descriptor_sets = 8;
    d.push_constants_size = 128;
    d.compute_shared_memory = 32768;
    d.workgroup_size[0] = 1024;
    d.workgroup_size[1] = 1024;
    d.workgroup_size[2] = 64;
    d.workgroup_invocations = 1024;
    d.workgroup_count[0] = d.workgroup_count[1] = d.workgroup_count[2] = 65535;
    d.image_dimension_2d = 16384;
    d.image_array_layers = 2048;
    d.storage_buffer_range = 1073741820;
    d.max_memory_allocation_size = 0;  // not in the 2023 block (no kernel need depends on it)
    return d;
  }();
  return l;
}

}  // namespace vsgl
