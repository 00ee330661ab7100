#include "harness/core/device_limits.hpp"

#include <iterator>

#include <nlohmann/json.hpp>

#include "harness/core/json_reader.hpp"
#include "harness/core/sorted_json.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;

// The 32-bit limits, by their key in the file; the three others (two 3-vectors and the 64-bit
// allocation size) and the format features are written out below.
struct Limit32 {
  const char* key;
  uint32_t DeviceLimits::*field;
};
constexpr Limit32 kLimits32[] = {
    {"maxPerStageDescriptorStorageImages", &DeviceLimits::per_stage_storage_images},
    {"maxPerStageDescriptorSampledImages", &DeviceLimits::per_stage_sampled_images},
    {"maxPerStageDescriptorSamplers", &DeviceLimits::per_stage_samplers},
    {"maxPerStageDescriptorStorageBuffers", &DeviceLimits::per_stage_storage_buffers},
    {"maxPerStageDescriptorUniformBuffers", &DeviceLimits::per_stage_uniform_buffers},
    {"maxPerStageResources", &DeviceLimits::per_stage_resources},
    {"maxDescriptorSetStorageImages", &DeviceLimits::set_storage_images},
    {"maxDescriptorSetSampledImages", &DeviceLimits::set_sampled_images},
    {"maxDescriptorSetSamplers", &DeviceLimits::set_samplers},
    {"maxDescriptorSetStorageBuffers", &DeviceLimits::set_storage_buffers},
    {"maxDescriptorSetUniformBuffers", &DeviceLimits::set_uniform_buffers},
    {"maxBoundDescriptorSets", &DeviceLimits::bound_descriptor_sets},
    {"maxPushConstantsSize", &DeviceLimits::push_constants_size},
    {"maxComputeSharedMemorySize", &DeviceLimits::compute_shared_memory},
    {"maxComputeWorkGroupInvocations", &DeviceLimits::workgroup_invocations},
    {"maxImageDimension2D", &DeviceLimits::image_dimension_2d},
    {"maxImageArrayLayers", &DeviceLimits::image_array_layers},
    {"maxStorageBufferRange", &DeviceLimits::storage_buffer_range},
    {"subgroupSize", &DeviceLimits::subgroup_size},
};
constexpr const char* kWorkgroupSize = "maxComputeWorkGroupSize";
constexpr const char* kWorkgroupCount = "maxComputeWorkGroupCount";
constexpr const char* kAllocationSize = "maxMemoryAllocationSize";
constexpr const char* kRgba32f = "rgba32f_optimal_tiling";
constexpr std::size_t kLimitKeyCount = std::size(kLimits32) + 4;  // + the two vectors, the size, the features

struct Feature {
  const char* key;
  bool Rgba32fFeatures::*field;
};
constexpr Feature kFeatures[] = {
    {"sampled_image", &Rgba32fFeatures::sampled_image},
    {"sampled_image_filter_linear", &Rgba32fFeatures::sampled_image_filter_linear},
    {"storage_image", &Rgba32fFeatures::storage_image},
    {"blit_src", &Rgba32fFeatures::blit_src},
    {"blit_dst", &Rgba32fFeatures::blit_dst},
};

std::array<uint32_t, 3> vector3(const JsonReader& r, const json& object, const std::string& parent,
                                std::string_view key) {
  const json& a = r.array(object, parent, key, 3);
  const std::string path = r.child(parent, key);
  std::array<uint32_t, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!a[i].is_number_unsigned() || a[i].get<uint64_t>() > UINT32_MAX)
      r.wrong_type(a[i], r.element(path, i), "an unsigned 32-bit integer");
    out[i] = a[i].get<uint32_t>();
  }
  return out;
}

}  // namespace

nlohmann::ordered_json to_json(const DeviceLimits& l) {
  json out = json::object();
  for (const Limit32& k : kLimits32) out[k.key] = l.*k.field;
  out[kWorkgroupSize] = l.workgroup_size;
  out[kWorkgroupCount] = l.workgroup_count;
  out[kAllocationSize] = l.max_memory_allocation_size;
  json features = json::object();
  for (const Feature& f : kFeatures) features[f.key] = l.rgba32f_optimal_tiling.*f.field;
  out[kRgba32f] = features;
  return sorted_keys(out);
}

DeviceLimits device_limits_from_json(const JsonReader& r, const json& l, const std::string& p) {
  DeviceLimits out;
  for (const Limit32& k : kLimits32) out.*k.field = r.uint32(l, p, k.key);
  out.workgroup_size = vector3(r, l, p, kWorkgroupSize);
  out.workgroup_count = vector3(r, l, p, kWorkgroupCount);
  out.max_memory_allocation_size = r.uint64(l, p, kAllocationSize);
  const json& f = r.object(l, p, kRgba32f);
  const std::string fp = r.child(p, kRgba32f);
  r.only_keys(f, fp, {"sampled_image", "sampled_image_filter_linear", "storage_image", "blit_src", "blit_dst"});
  for (const Feature& k : kFeatures) out.rgba32f_optimal_tiling.*k.field = r.boolean(f, fp, k.key);
  // Every key above is required, so one more is one the model would drop: refuse it.
  if (l.size() != kLimitKeyCount)
    for (const auto& [key, value] : l.items()) {
      bool known = key == kWorkgroupSize || key == kWorkgroupCount || key == kAllocationSize || key == kRgba32f;
      for (const Limit32& k : kLimits32) known = known || key == k.key;
      if (!known) r.fail(r.child(p, key), "is not a known limit");
    }
  return out;
}

}  // namespace vsgl
