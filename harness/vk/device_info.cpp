#include "harness/vk/device_info.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "harness/core/error.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {

const char* device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
  }
}

std::string api_version_string(uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

std::string driver_version_string(const DeviceInfo& info) {
  const uint32_t v = info.driver_version;
  if (info.vendor_id == 0x10DE)  // NVIDIA packs 10.8.8.6 bits
    return std::to_string((v >> 22) & 0x3ff) + "." + std::to_string((v >> 14) & 0xff) + "." +
           std::to_string((v >> 6) & 0xff) + "." + std::to_string(v & 0x3f);
  return api_version_string(v);
}

std::vector<DeviceInfo> enumerate_devices(VkInstance instance) {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> handles(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, handles.data()));

  std::vector<DeviceInfo> out;
  for (uint32_t i = 0; i < count; ++i) {
    DeviceInfo d;
    d.index = i;
    d.handle = handles[i];
    VkPhysicalDeviceProperties base{};
    vkGetPhysicalDeviceProperties(handles[i], &base);
    d.name = base.deviceName;
    d.type = base.deviceType;
    d.vendor_id = base.vendorID;
    d.device_id = base.deviceID;
    d.api_version = base.apiVersion;
    d.driver_version = base.driverVersion;
    d.timestamp_period_ns = base.limits.timestampPeriod;
    d.timestamp_compute_and_graphics = base.limits.timestampComputeAndGraphics == VK_TRUE;
    d.max_shared_memory = base.limits.maxComputeSharedMemorySize;
    for (int k = 0; k < 3; ++k) d.max_workgroup_count[k] = base.limits.maxComputeWorkGroupCount[k];
    d.max_workgroup_invocations = base.limits.maxComputeWorkGroupInvocations;
    d.sub_texel_precision_bits = base.limits.subTexelPrecisionBits;
    d.mipmap_precision_bits = base.limits.mipmapPrecisionBits;
    VkFormatProperties rgba32f{};
    vkGetPhysicalDeviceFormatProperties(handles[i], VK_FORMAT_R32G32B32A32_SFLOAT, &rgba32f);
    d.rgba32f_features = rgba32f.optimalTilingFeatures;
    d.limits = read_device_limits(base, 0, 0, d.rgba32f_features);

    if (d.api_version < VK_API_VERSION_1_2) {
      d.unusable_reason = "supports Vulkan " + api_version_string(d.api_version) + ", vsgl-bench needs 1.2";
      out.push_back(d);
      continue;
    }
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    maintenance3.pNext = &driver;
    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    subgroup.pNext = &maintenance3;
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(handles[i], &props2);
    d.driver_name = driver.driverName;
    d.driver_info = driver.driverInfo;
    d.subgroup_size = subgroup.subgroupSize;
    d.limits = read_device_limits(base, maintenance3.maxMemoryAllocationSize, d.subgroup_size, d.rgba32f_features);

    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(handles[i], &features);
    d.pipeline_statistics = features.pipelineStatisticsQuery == VK_TRUE;

    VkPhysicalDeviceMemoryProperties mem{};
    vkGetPhysicalDeviceMemoryProperties(handles[i], &mem);
    for (uint32_t h = 0; h < mem.memoryHeapCount; ++h)
      if (mem.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) d.device_local_bytes += mem.memoryHeaps[h].size;

    // Prefer a family that does compute and graphics with timestamps, then compute with
    // timestamps, then compute alone (usable for nothing timed; reported as such).
    uint32_t qcount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(handles[i], &qcount, nullptr);
    std::vector<VkQueueFamilyProperties> families(qcount);
    vkGetPhysicalDeviceQueueFamilyProperties(handles[i], &qcount, families.data());
    int best_score = -1;
    for (uint32_t f = 0; f < qcount; ++f) {
      const auto flags = families[f].queueFlags;
      if (!(flags & VK_QUEUE_COMPUTE_BIT)) continue;
      const bool gfx = (flags & VK_QUEUE_GRAPHICS_BIT) != 0;
      const bool ts = families[f].timestampValidBits > 0;
      const int score = (ts ? 2 : 0) + (gfx ? 1 : 0);
      if (score > best_score) {
        best_score = score;
        d.compute_queue_family = f;
        d.graphics = gfx;
        d.timestamp_valid_bits = families[f].timestampValidBits;
      }
    }
    if (d.compute_queue_family == UINT32_MAX) d.unusable_reason = "has no compute queue";
    out.push_back(d);
  }
  return out;
}

namespace {
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}
int type_rank(VkPhysicalDeviceType t) {
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}
}  // namespace

const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices, const std::string& spec) {
  if (devices.empty())
    throw DeviceError("no Vulkan device found: install a driver (mesa-vulkan-drivers gives the lavapipe CPU device)");
  const DeviceInfo* chosen = nullptr;
  if (spec.empty()) {
    for (const auto& d : devices)
      if (d.usable() && (chosen == nullptr || type_rank(d.type) < type_rank(chosen->type))) chosen = &d;
    if (chosen == nullptr)
      throw DeviceError("no usable Vulkan device:\n" + describe_devices_text(devices));
    return *chosen;
  }
  const bool numeric = std::all_of(spec.begin(), spec.end(), [](unsigned char c) { return std::isdigit(c); });
  if (numeric) {
    const unsigned long idx = std::stoul(spec);
    if (idx >= devices.size())
      throw DeviceError("unknown device '" + spec + "': there are " + std::to_string(devices.size()) +
                        " devices (see 'vsgl-bench devices')");
    chosen = &devices[idx];
  } else {
    for (const auto& d : devices)
      if (lower(d.name).find(lower(spec)) != std::string::npos) {
        chosen = &d;
        break;
      }
    if (chosen == nullptr)
      throw DeviceError("unknown device '" + spec + "': no device name contains it. Devices:\n" +
                        describe_devices_text(devices));
  }
  if (!chosen->usable())
    throw DeviceError("device " + std::to_string(chosen->index) + " (" + chosen->name +
                      ") cannot be used: " + chosen->unusable_reason);
  return *chosen;
}

DeviceRecord device_record(const DeviceInfo& d) {
  DeviceRecord r;
  r.index = d.index;
  r.name = d.name;
  r.type = device_type_name(d.type);
  r.vendor_id = d.vendor_id;
  r.device_id = d.device_id;
  r.api_version = api_version_string(d.api_version);
  r.driver_version = driver_version_string(d);
  r.driver_name = d.driver_name;
  r.driver_info = d.driver_info;
  r.queue_family = d.compute_queue_family == UINT32_MAX ? -1 : static_cast<int64_t>(d.compute_queue_family);
  r.graphics = d.graphics;
  r.timestamps = d.timestamps();
  r.timestamp_valid_bits = d.timestamp_valid_bits;
  r.timestamp_period_ns = d.timestamp_period_ns;
  r.pipeline_statistics = d.pipeline_statistics;
  r.subgroup_size = d.subgroup_size;
  r.max_compute_shared_memory = d.max_shared_memory;
  r.device_local_bytes = d.device_local_bytes;
  r.limits = d.limits;
  r.usable = d.usable();
  r.unusable_reason = d.unusable_reason;
  return r;
}

std::string describe_devices_text(const std::vector<DeviceInfo>& devices) {
  std::ostringstream os;
  for (const auto& d : devices) {
    os << "  [" << d.index << "] " << d.name << "\n"
       << "      type " << device_type_name(d.type) << ", Vulkan " << api_version_string(d.api_version)
       << ", driver " << (d.driver_name.empty() ? "?" : d.driver_name) << " " << driver_version_string(d);
    if (!d.driver_info.empty()) os << " (" << d.driver_info << ")";
    os << "\n      timestamps: ";
    if (d.timestamps())
      os << d.timestamp_valid_bits << " valid bits, period " << d.timestamp_period_ns << " ns";
    else
      os << "not supported";
    os << "; subgroup " << d.subgroup_size << "; shared memory " << d.max_shared_memory << " B";
    os << (d.usable() ? "" : "\n      unusable: " + d.unusable_reason) << "\n";
  }
  return os.str();
}

}  // namespace vsgl
