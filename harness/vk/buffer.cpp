#include "harness/vk/buffer.hpp"

#include <cstring>

#include "harness/vk/device.hpp"
#include "harness/core/error.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {
namespace {

void barrier(VkCommandBuffer cmd, VkPipelineStageFlags src_stage, VkAccessFlags src, VkPipelineStageFlags dst_stage,
             VkAccessFlags dst) {
  VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  b.srcAccessMask = src;
  b.dstAccessMask = dst;
  vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

}  // namespace

Buffer::Buffer(Device& device, VkDeviceSize size, MemoryUsage usage, const std::string& name,
               VkBufferUsageFlags extra_usage)
    : device_(device.get()), size_(size), name_(name) {
  if (size == 0) throw InputError("buffer '" + name + "' would be empty");
  // One buffer is one allocation (maintenance3's maxMemoryAllocationSize; 0: not reported).
  const uint64_t max_allocation = device.info().limits.max_memory_allocation_size;
  if (max_allocation > 0 && size > max_allocation)
    throw DeviceError(device.info().name + " cannot allocate buffer '" + name + "': it needs " + std::to_string(size) +
                      " bytes where the device allows " + std::to_string(max_allocation) + " (maxMemoryAllocationSize)");
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  switch (usage) {
    case MemoryUsage::kDeviceLocal:
      info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                   VK_BUFFER_USAGE_TRANSFER_DST_BIT | extra_usage;
      break;
    case MemoryUsage::kUpload:
      info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | extra_usage;
      break;
    case MemoryUsage::kReadback:
      info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT | extra_usage;
      break;
  }
  VkBuffer buffer = VK_NULL_HANDLE;
  VK_CHECK(vkCreateBuffer(device_, &info, nullptr, &buffer));
  buffer_ = UniqueHandle<VkBuffer>(device_, buffer, vkDestroyBuffer);
  device.set_name(buffer, VK_OBJECT_TYPE_BUFFER, name);

  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(device_, buffer, &req);
  if (usage == MemoryUsage::kDeviceLocal)
    memory_ = device.allocate_memory(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, "buffer " + name);
  else
    memory_ = device.allocate_memory(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                     usage == MemoryUsage::kReadback ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT : 0,
                                     "buffer " + name);
  VkDeviceMemory memory = memory_.get();
  VK_CHECK(vkBindBufferMemory(device_, buffer, memory, 0));
  if (usage != MemoryUsage::kDeviceLocal) VK_CHECK(vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, &mapped_));
}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  if (this != &o) {
    // The memory is unmapped implicitly when freed; release it after the buffer.
    buffer_ = std::move(o.buffer_);
    memory_ = std::move(o.memory_);
    device_ = o.device_;
    size_ = o.size_;
    mapped_ = std::exchange(o.mapped_, nullptr);
    name_ = std::move(o.name_);
  }
  return *this;
}

Buffer::~Buffer() {
  buffer_.reset();
  memory_.reset();
}

void upload(Device& device, const Buffer& dst, const void* data, std::size_t bytes, VkDeviceSize offset) {
  if (bytes == 0) return;
  if (offset + bytes > dst.size()) throw InputError("upload past the end of buffer '" + dst.name() + "'");
  Buffer staging(device, bytes, MemoryUsage::kUpload, dst.name() + ".staging");
  std::memcpy(staging.mapped(), data, bytes);
  device.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        barrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT,
                VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        VkBufferCopy region{0, offset, bytes};
        vkCmdCopyBuffer(cmd, staging.get(), dst.get(), 1, &region);
        barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
      },
      "upload " + dst.name());
}

void download(Device& device, const Buffer& src, void* data, std::size_t bytes, VkDeviceSize offset) {
  if (bytes == 0) return;
  if (offset + bytes > src.size()) throw InputError("download past the end of buffer '" + src.name() + "'");
  Buffer readback(device, bytes, MemoryUsage::kReadback, src.name() + ".readback");
  device.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        barrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferCopy region{offset, 0, bytes};
        vkCmdCopyBuffer(cmd, src.get(), readback.get(), 1, &region);
        barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                VK_ACCESS_HOST_READ_BIT);
      },
      "download " + src.name());
  std::memcpy(data, readback.mapped(), bytes);
}

}  // namespace vsgl
