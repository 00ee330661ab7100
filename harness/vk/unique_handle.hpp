#pragma once
// A move-only owner of one device-level Vulkan handle, destroyed with the vkDestroy*/vkFree*
// function it was given (they all share the (VkDevice, Handle, allocator) signature).
#include <vulkan/vulkan.h>

#include <utility>

namespace vsgl {

template <class Handle>
class UniqueHandle {
 public:
  using Destroy = void (*)(VkDevice, Handle, const VkAllocationCallbacks*);

  UniqueHandle() = default;
  UniqueHandle(VkDevice device, Handle handle, Destroy destroy)
      : device_(device), handle_(handle), destroy_(destroy) {}
  UniqueHandle(const UniqueHandle&) = delete;
  UniqueHandle& operator=(const UniqueHandle&) = delete;
  UniqueHandle(UniqueHandle&& o) noexcept
      : device_(o.device_), handle_(std::exchange(o.handle_, Handle{})), destroy_(o.destroy_) {}
  UniqueHandle& operator=(UniqueHandle&& o) noexcept {
    if (this != &o) {
      reset();
      device_ = o.device_;
      handle_ = std::exchange(o.handle_, Handle{});
      destroy_ = o.destroy_;
    }
    return *this;
  }
  ~UniqueHandle() { reset(); }

  void reset() {
    if (handle_ != Handle{} && destroy_ != nullptr) destroy_(device_, handle_, nullptr);
    handle_ = Handle{};
  }
  Handle get() const { return handle_; }
  explicit operator bool() const { return handle_ != Handle{}; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_{};
  Destroy destroy_ = nullptr;
};

}  // namespace vsgl
