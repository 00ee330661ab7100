#include "harness/vk/instance.hpp"

#include <cstdio>
#include <cstring>

#include "harness/core/error.hpp"
#include "harness/core/version.hpp"
#include "harness/vk/extension_choice.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool has_layer(const char* name) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
  std::vector<VkLayerProperties> layers(count);
  VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

std::vector<std::string> instance_extensions() {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> exts(count);
  VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, exts.data()));
  std::vector<std::string> names;
  for (uint32_t i = 0; i < count; ++i) names.emplace_back(exts[i].extensionName);
  return names;
}

}  // namespace

Instance::Instance(const InstanceOptions& options) : validation_(options.validation), quiet_(options.quiet_validation) {
  uint32_t loader_version = VK_API_VERSION_1_0;
  if (vkEnumerateInstanceVersion(&loader_version) != VK_SUCCESS || loader_version < VK_API_VERSION_1_2)
    throw DeviceError("the Vulkan loader supports only Vulkan " + std::to_string(VK_API_VERSION_MAJOR(loader_version)) +
                      "." + std::to_string(VK_API_VERSION_MINOR(loader_version)) +
                      "; vsgl-bench needs Vulkan 1.2 (install libvulkan1 >= 1.2)");

  std::vector<const char*> layers;
  if (validation_) {
    if (!has_layer(kValidationLayer))
      throw DeviceError(
          "--validate needs the Khronos validation layer (VK_LAYER_KHRONOS_validation), which is not "
          "installed: install the Debian package vulkan-validationlayers");
    layers.push_back(kValidationLayer);
  }
  // Debug utils where offered; portability enumeration (MoltenVK's devices) where offered.
  const InstanceExtensionChoice choice = choose_instance_extensions(instance_extensions());
  debug_utils_ = choice.debug_utils;
  if (validation_ && !debug_utils_)
    throw DeviceError("--validate needs VK_EXT_debug_utils to receive validation messages");

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "vsgl-bench";
  app.applicationVersion = VK_MAKE_API_VERSION(0, kVersionMajor, kVersionMinor, kVersionPatch);
  app.pEngineName = "vsgl-bench";
  app.apiVersion = VK_API_VERSION_1_2;

  const VkValidationFeatureEnableEXT sync_enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  const VkValidationFeatureEnableEXT gpu_av_enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_EXT, VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_RESERVE_BINDING_SLOT_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  if (options.gpu_assisted) {
    features.enabledValidationFeatureCount = 2;
    features.pEnabledValidationFeatures = gpu_av_enables;
  } else {
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = sync_enables;
  }

  VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = &Instance::on_message;
  messenger_info.pUserData = this;
  if (validation_) {
    // Chained so that messages from vkCreateInstance itself are counted too.
    features.pNext = &messenger_info;
  }

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = validation_ ? &features : nullptr;
  info.flags = choice.flags;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(choice.extensions.size());
  info.ppEnabledExtensionNames = choice.extensions.data();
  const VkResult r = vkCreateInstance(&info, nullptr, &instance_);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw DeviceError("no Vulkan driver found (VK_ERROR_INCOMPATIBLE_DRIVER): install a Vulkan driver, e.g. "
                      "the Debian package mesa-vulkan-drivers for lavapipe");
  VK_CHECK(r);

  if (debug_utils_) {
    set_object_name_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
  }
  if (validation_) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (create == nullptr) throw DeviceError("vkCreateDebugUtilsMessengerEXT is missing");
    VK_CHECK(create(instance_, &messenger_info, nullptr, &messenger_));
  }
}

Instance::~Instance() {
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy != nullptr) destroy(instance_, messenger_, nullptr);
  }
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

std::vector<std::string> Instance::validation_messages() const {
  std::lock_guard<std::mutex> lock(messages_mutex_);
  return messages_;
}

void Instance::clear_validation_messages() {
  std::lock_guard<std::mutex> lock(messages_mutex_);
  messages_.clear();
  errors_ = 0;
}

void Instance::set_name(VkDevice device, VkObjectType type, uint64_t handle, const std::string& name) const {
  if (set_object_name_ == nullptr || handle == 0) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name.c_str();
  VK_CHECK(set_object_name_(device, &info));
}

VkBool32 VKAPI_PTR Instance::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<Instance*>(user);
  const bool error = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
  const std::string text = std::string(error ? "validation error: " : "validation warning: ") +
                           (data && data->pMessage ? data->pMessage : "(no message)");
  if (error) ++self->errors_;
  {
    std::lock_guard<std::mutex> lock(self->messages_mutex_);
    self->messages_.push_back(text);
  }
  if (!self->quiet_) std::fprintf(stderr, "%s\n", text.c_str());
  return VK_FALSE;
}

}  // namespace vsgl
