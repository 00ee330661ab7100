#pragma once
// The logical device: one queue (compute, and graphics where the family has it), a transient
// command pool for one-shot work, memory-type lookup and debug naming.
#include <vulkan/vulkan.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "harness/vk/device_info.hpp"
#include "harness/vk/instance.hpp"
#include "harness/vk/unique_handle.hpp"

namespace vsgl {

class Device {
 public:
  Device(const Instance& instance, const DeviceInfo& info);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  VkDevice get() const { return device_; }
  VkPhysicalDevice physical() const { return info_.handle; }
  VkQueue queue() const { return queue_; }
  const DeviceInfo& info() const { return info_; }
  const Instance& instance() const { return instance_; }
  bool pipeline_statistics_enabled() const { return pipeline_statistics_; }

  template <class Handle>
  void set_name(Handle handle, VkObjectType type, const std::string& name) const {
    instance_.set_name(device_, type, reinterpret_cast<uint64_t>(handle), name);
  }

  // Index of a memory type allowed by `type_bits` having `required` flags, preferring `preferred`.
  uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred = 0) const;
  // Memory for a resource with requirements `req`, from such a type, named "<what>.memory".
  // Running out of memory is a DeviceError naming `what` and the size, not a bare VkResult.
  UniqueHandle<VkDeviceMemory> allocate_memory(const VkMemoryRequirements& req, VkMemoryPropertyFlags required,
                                               VkMemoryPropertyFlags preferred, const std::string& what);

  // Records one-shot work into a fresh primary command buffer, submits it and waits for it.
  void submit_and_wait(const std::function<void(VkCommandBuffer)>& record, const std::string& what = "one-shot work");

  VkCommandBuffer allocate_command_buffer(const std::string& name);
  void free_command_buffer(VkCommandBuffer cmd);
  // Submits a recorded command buffer and waits for it (the replay of timed work).
  void submit_and_wait(VkCommandBuffer cmd);

 private:
  const Instance& instance_;
  DeviceInfo info_;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory_{};
  bool pipeline_statistics_ = false;
};

// Instance + chosen device, as one owner for the CLI and tests.
struct GpuContextOptions {
  InstanceOptions instance;
  std::string device;  // --device: empty, index or name substring
};

class GpuContext {
 public:
  explicit GpuContext(const GpuContextOptions& options);
  Instance& instance() { return *instance_; }
  Device& device() { return *device_; }
  const std::vector<DeviceInfo>& devices() const { return devices_; }

 private:
  std::unique_ptr<Instance> instance_;
  std::vector<DeviceInfo> devices_;
  std::unique_ptr<Device> device_;
};

}  // namespace vsgl
