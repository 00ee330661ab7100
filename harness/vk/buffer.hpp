#pragma once
// A VkBuffer with its own memory allocation (the suite allocates a few dozen buffers, so a
// sub-allocator would buy nothing), and the staging uploads/downloads that move data to it.
#include <vulkan/vulkan.h>

#include <cstddef>
#include <string>
#include <vector>

#include "harness/vk/unique_handle.hpp"

namespace vsgl {

class Device;

enum class MemoryUsage {
  kDeviceLocal,  // storage for kernels; filled by upload(), read by download()
  kUpload,       // host-visible staging, written by the host
  kReadback,     // host-visible, read by the host after a copy
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(Device& device, VkDeviceSize size, MemoryUsage usage, const std::string& name,
         VkBufferUsageFlags extra_usage = 0);
  Buffer(Buffer&&) noexcept = default;
  Buffer& operator=(Buffer&&) noexcept;
  ~Buffer();
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer get() const { return buffer_.get(); }
  VkDeviceSize size() const { return size_; }
  const std::string& name() const { return name_; }
  void* mapped() const { return mapped_; }  // non-null for kUpload / kReadback

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  UniqueHandle<VkBuffer> buffer_;
  UniqueHandle<VkDeviceMemory> memory_;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
  std::string name_;
};

// Copies host data into a device-local buffer through a staging buffer. The copy ends with a
// barrier that makes it visible to any later command on the queue.
void upload(Device& device, const Buffer& dst, const void* data, std::size_t bytes, VkDeviceSize offset = 0);
// Copies a device buffer's range back to the host, after making all earlier writes visible.
void download(Device& device, const Buffer& src, void* data, std::size_t bytes, VkDeviceSize offset = 0);

template <class T>
std::vector<T> download_vector(Device& device, const Buffer& src, std::size_t count, VkDeviceSize offset = 0) {
  std::vector<T> out(count);
  download(device, src, out.data(), count * sizeof(T), offset);
  return out;
}

}  // namespace vsgl
