#include "harness/vk/device.hpp"

#include <sstream>

#include "harness/core/error.hpp"
#include "harness/vk/extension_choice.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {
namespace {

std::vector<std::string> device_extensions(VkPhysicalDevice physical) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> exts(count);
  VK_CHECK(vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, exts.data()));
  std::vector<std::string> names;
  for (uint32_t i = 0; i < count; ++i) names.emplace_back(exts[i].extensionName);
  return names;
}

}  // namespace

Device::Device(const Instance& instance, const DeviceInfo& info) : instance_(instance), info_(info) {
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = info.compute_queue_family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(info.handle, &supported);
  VkPhysicalDeviceFeatures enabled{};
  enabled.pipelineStatisticsQuery = supported.pipelineStatisticsQuery;
  pipeline_statistics_ = supported.pipelineStatisticsQuery == VK_TRUE;

  // VK_KHR_portability_subset where the device lists it (MoltenVK): the specification requires it.
  const std::vector<const char*> extensions = choose_device_extensions(device_extensions(info.handle));

  VkDeviceCreateInfo create{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  create.queueCreateInfoCount = 1;
  create.pQueueCreateInfos = &queue_info;
  create.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  create.ppEnabledExtensionNames = extensions.data();
  create.pEnabledFeatures = &enabled;
  VK_CHECK(vkCreateDevice(info.handle, &create, nullptr, &device_));
  vkGetDeviceQueue(device_, info.compute_queue_family, 0, &queue_);
  vkGetPhysicalDeviceMemoryProperties(info.handle, &memory_);

  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = info.compute_queue_family;
  VK_CHECK(vkCreateCommandPool(device_, &pool_info, nullptr, &pool_));
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(vkCreateFence(device_, &fence_info, nullptr, &fence_));
  set_name(queue_, VK_OBJECT_TYPE_QUEUE, "vsgl.queue");
  set_name(pool_, VK_OBJECT_TYPE_COMMAND_POOL, "vsgl.command_pool");
  set_name(fence_, VK_OBJECT_TYPE_FENCE, "vsgl.fence");
}

Device::~Device() {
  if (device_ == VK_NULL_HANDLE) return;
  vkDeviceWaitIdle(device_);
  vkDestroyFence(device_, fence_, nullptr);
  vkDestroyCommandPool(device_, pool_, nullptr);
  vkDestroyDevice(device_, nullptr);
}

uint32_t Device::memory_type(uint32_t type_bits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) const {
  int fallback = -1;
  for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if (!(type_bits & (1u << i))) continue;
    const auto flags = memory_.memoryTypes[i].propertyFlags;
    if ((flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (fallback < 0) fallback = static_cast<int>(i);
  }
  if (fallback < 0) throw DeviceError("device " + info_.name + " has no memory type with the required properties");
  return static_cast<uint32_t>(fallback);
}

UniqueHandle<VkDeviceMemory> Device::allocate_memory(const VkMemoryRequirements& req, VkMemoryPropertyFlags required,
                                                     VkMemoryPropertyFlags preferred, const std::string& what) {
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, required, preferred);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  const VkResult r = vkAllocateMemory(device_, &alloc, nullptr, &memory);
  if (r == VK_ERROR_OUT_OF_DEVICE_MEMORY || r == VK_ERROR_OUT_OF_HOST_MEMORY) {
    std::ostringstream os;
    os << "out of device memory allocating '" << what << "' (" << (static_cast<double>(req.size) / (1 << 20))
       << " MiB) on " << info_.name;
    throw DeviceLimitError(os.str());
  }
  VK_CHECK(r);
  set_name(memory, VK_OBJECT_TYPE_DEVICE_MEMORY, what + ".memory");
  return UniqueHandle<VkDeviceMemory>(device_, memory, vkFreeMemory);
}

VkCommandBuffer Device::allocate_command_buffer(const std::string& name) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &cmd));
  set_name(cmd, VK_OBJECT_TYPE_COMMAND_BUFFER, name);
  return cmd;
}

void Device::free_command_buffer(VkCommandBuffer cmd) { vkFreeCommandBuffers(device_, pool_, 1, &cmd); }

void Device::submit_and_wait(VkCommandBuffer cmd) {
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  VK_CHECK(vkResetFences(device_, 1, &fence_));
  VK_CHECK(vkQueueSubmit(queue_, 1, &submit, fence_));
  VK_CHECK(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
}

void Device::submit_and_wait(const std::function<void(VkCommandBuffer)>& record, const std::string& what) {
  VkCommandBuffer cmd = allocate_command_buffer(what);
  try {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    record(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));
    submit_and_wait(cmd);
  } catch (...) {
    free_command_buffer(cmd);
    throw;
  }
  free_command_buffer(cmd);
}

GpuContext::GpuContext(const GpuContextOptions& options) {
  instance_ = std::make_unique<Instance>(options.instance);
  devices_ = enumerate_devices(instance_->get());
  const DeviceInfo& chosen = select_device(devices_, options.device);
  device_ = std::make_unique<Device>(*instance_, chosen);
}

}  // namespace vsgl
