#include "harness/vk/vk_check.hpp"

#include <sstream>

namespace vsgl {

const char* vk_result_name(VkResult result) {
  switch (result) {
#define VSGL_CASE(r) \
  case r:            \
    return #r;
    VSGL_CASE(VK_SUCCESS)
    VSGL_CASE(VK_NOT_READY)
    VSGL_CASE(VK_TIMEOUT)
    VSGL_CASE(VK_EVENT_SET)
    VSGL_CASE(VK_EVENT_RESET)
    VSGL_CASE(VK_INCOMPLETE)
    VSGL_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    VSGL_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    VSGL_CASE(VK_ERROR_INITIALIZATION_FAILED)
    VSGL_CASE(VK_ERROR_DEVICE_LOST)
    VSGL_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    VSGL_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    VSGL_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    VSGL_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    VSGL_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    VSGL_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    VSGL_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    VSGL_CASE(VK_ERROR_FRAGMENTED_POOL)
    VSGL_CASE(VK_ERROR_UNKNOWN)
    VSGL_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    VSGL_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    VSGL_CASE(VK_ERROR_FRAGMENTATION)
    VSGL_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    VSGL_CASE(VK_PIPELINE_COMPILE_REQUIRED)
    VSGL_CASE(VK_ERROR_SURFACE_LOST_KHR)
    VSGL_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    VSGL_CASE(VK_SUBOPTIMAL_KHR)
    VSGL_CASE(VK_ERROR_OUT_OF_DATE_KHR)
    VSGL_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
#undef VSGL_CASE
    default:
      return "VK_RESULT_UNKNOWN";
  }
}

void throw_vk_error(VkResult result, const char* call, const char* file, int line) {
  std::ostringstream os;
  os << call << " failed with " << vk_result_name(result) << " (" << file << ":" << line << ")";
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    os << ": the device ran out of memory; try smaller captures or fewer VSGLs";
  else if (result == VK_ERROR_DEVICE_LOST)
    os << ": the device was lost (driver reset or hang); results of this run are discarded";
  throw VulkanError(result, os.str());
}

}  // namespace vsgl
