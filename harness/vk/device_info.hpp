#pragma once
// What vsgl-bench knows about each physical device, and the choice among them.
// Selection is explicit about why: an unusable device carries the reason it was rejected.
#include <vulkan/vulkan.h>

#include "harness/formats/run_header.hpp"
#include "harness/vk/device_limits.hpp"

#include <optional>
#include <string>
#include <vector>

namespace vsgl {

struct DeviceInfo {
  uint32_t index = 0;
  VkPhysicalDevice handle = VK_NULL_HANDLE;
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t vendor_id = 0;
  uint32_t device_id = 0;
  uint32_t api_version = 0;
  uint32_t driver_version = 0;
  std::string driver_name;  // VkPhysicalDeviceDriverProperties (Vulkan 1.2)
  std::string driver_info;
  uint32_t compute_queue_family = UINT32_MAX;  // best family: compute (+graphics) with timestamps
  bool graphics = false;                       // that family also does graphics (the recorder needs it)
  uint32_t timestamp_valid_bits = 0;           // of that family; 0 = no timestamps
  float timestamp_period_ns = 0.0f;
  bool timestamp_compute_and_graphics = false;
  bool pipeline_statistics = false;
  uint32_t subgroup_size = 0;
  uint32_t max_shared_memory = 0;
  uint32_t max_workgroup_count[3] = {0, 0, 0};
  uint32_t max_workgroup_invocations = 0;
  uint64_t device_local_bytes = 0;
  // How finely the sampler resolves positions and levels (DESIGN.md §6.1a): bilinear weights are
  // multiples of 2^-sub_texel_precision_bits, the level fraction of 2^-mipmap_precision_bits.
  uint32_t sub_texel_precision_bits = 0;
  uint32_t mipmap_precision_bits = 0;
  VkFormatFeatureFlags rgba32f_features = 0;  // optimal tiling features of VK_FORMAT_R32G32B32A32_SFLOAT
  DeviceLimits limits;  // every limit a kernel or capture depends on; checked before each pipeline
  std::string unusable_reason;  // empty = usable

  bool usable() const { return unusable_reason.empty(); }
  bool timestamps() const { return timestamp_valid_bits > 0 && timestamp_period_ns > 0.0f; }
};

const char* device_type_name(VkPhysicalDeviceType type);
std::string api_version_string(uint32_t version);
std::string driver_version_string(const DeviceInfo& info);

std::vector<DeviceInfo> enumerate_devices(VkInstance instance);

// The device a run uses. `spec` is empty (default: first usable discrete GPU, else integrated,
// else virtual, else CPU such as lavapipe), a decimal index, or a case-insensitive substring of
// the device name. Throws DeviceError naming the candidates when nothing matches.
const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices, const std::string& spec);

// The device as every output document records it (formats/run_header.hpp): the one place a
// DeviceInfo becomes a document's device.
DeviceRecord device_record(const DeviceInfo& info);
std::string describe_devices_text(const std::vector<DeviceInfo>& devices);

}  // namespace vsgl
