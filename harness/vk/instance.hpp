#pragma once
// The Vulkan instance, optionally with the Khronos validation layer (synchronization validation
// on). Validation messages are printed and counted; a run with validation on fails if any error
// was reported (ValidationReport::errors()).
#include <vulkan/vulkan.h>

#include <atomic>
#include <mutex>
#include <string>
#include <vector>

namespace vsgl {

struct InstanceOptions {
  bool validation = false;   // VK_LAYER_KHRONOS_validation + synchronization validation
  bool quiet_validation = false;  // count but do not print messages (tests that provoke errors)
  // With validation: the layer's GPU-assisted mode (instrumented shaders report out-of-bounds
  // descriptor accesses) instead of synchronization validation (tests/test_instance_gpu_assisted).
  bool gpu_assisted = false;
};

class Instance {
 public:
  explicit Instance(const InstanceOptions& options = {});
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  VkInstance get() const { return instance_; }
  bool validation_enabled() const { return validation_; }

  // Validation messages of severity ERROR seen so far (warnings are printed, not counted).
  uint32_t validation_errors() const { return errors_.load(); }
  std::vector<std::string> validation_messages() const;
  void clear_validation_messages();

  // Name a device-level object so validation messages say which buffer or pipeline they mean.
  void set_name(VkDevice device, VkObjectType type, uint64_t handle, const std::string& name) const;

 private:
  static VkBool32 VKAPI_PTR on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                        VkDebugUtilsMessageTypeFlagsEXT types,
                                        const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  PFN_vkSetDebugUtilsObjectNameEXT set_object_name_ = nullptr;
  bool validation_ = false;
  bool debug_utils_ = false;
  bool quiet_ = false;
  std::atomic<uint32_t> errors_{0};
  mutable std::mutex messages_mutex_;
  std::vector<std::string> messages_;
};

}  // namespace vsgl
