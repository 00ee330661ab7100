#include "harness/timing/copy_bandwidth.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>

#include "harness/core/error.hpp"
#include "harness/core/statistics.hpp"
#include "harness/timing/timing_runner.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/vk/timestamp_pool.hpp"
#include "harness/vk/unique_handle.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {
namespace {

std::string mib(uint64_t bytes) {
  const double m = static_cast<double>(bytes) / static_cast<double>(1ull << 20);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g MiB", m);
  return buf;
}

// Sizes are kept a multiple of 256 bytes (vkCmdFillBuffer and vkCmdCopyBuffer need 4).
uint64_t aligned(uint64_t bytes) { return bytes & ~uint64_t{255}; }

// One device-local transfer buffer with its memory, allocated here rather than through Buffer so
// that running out of memory is an answer (try a smaller size), not an error.
struct CopyBuffer {
  UniqueHandle<VkDeviceMemory> memory;  // declared first: destroyed after the buffer bound to it
  UniqueHandle<VkBuffer> buffer;
};

bool out_of_memory(VkResult r) { return r == VK_ERROR_OUT_OF_DEVICE_MEMORY || r == VK_ERROR_OUT_OF_HOST_MEMORY; }

std::optional<CopyBuffer> try_allocate(Device& device, uint64_t bytes, const std::string& name) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = bytes;
  info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkResult r = vkCreateBuffer(device.get(), &info, nullptr, &buffer);
  if (out_of_memory(r)) return std::nullopt;
  VK_CHECK(r);
  CopyBuffer out;
  out.buffer = UniqueHandle<VkBuffer>(device.get(), buffer, vkDestroyBuffer);
  device.set_name(buffer, VK_OBJECT_TYPE_BUFFER, name);
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(device.get(), buffer, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = device.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  r = vkAllocateMemory(device.get(), &alloc, nullptr, &memory);
  if (out_of_memory(r)) return std::nullopt;
  VK_CHECK(r);
  out.memory = UniqueHandle<VkDeviceMemory>(device.get(), memory, vkFreeMemory);
  device.set_name(memory, VK_OBJECT_TYPE_DEVICE_MEMORY, name + ".memory");
  VK_CHECK(vkBindBufferMemory(device.get(), buffer, memory, 0));
  return out;
}

struct Pair {
  CopyBuffer src, dst;
};

std::optional<Pair> try_allocate_pair(Device& device, uint64_t bytes) {
  std::optional<CopyBuffer> src = try_allocate(device, bytes, "copy_bandwidth.src");
  if (!src) return std::nullopt;
  std::optional<CopyBuffer> dst = try_allocate(device, bytes, "copy_bandwidth.dst");
  if (!dst) return std::nullopt;
  return Pair{std::move(*src), std::move(*dst)};
}

}  // namespace

CopySizePlan plan_copy_size(uint64_t requested, uint64_t max_allocation, uint64_t largest_heap) {
  CopySizePlan p;
  p.bytes = aligned(requested);
  if (max_allocation > 0 && p.bytes > max_allocation) {
    p.bytes = aligned(max_allocation);
    p.reduced_because = "maxMemoryAllocationSize is " + mib(max_allocation);
  }
  if (largest_heap > 0 && p.bytes > largest_heap / 4) {
    p.bytes = aligned(largest_heap / 4);
    p.reduced_because = "two buffers may take half of the largest device-local heap (" + mib(largest_heap) + ")";
  }
  return p;
}

void CopyBandwidthOptions::check() const {
  if (copies < 1) throw UsageError("the copy-bandwidth measurement needs at least one timed copy");
  if (bytes < (64u << 10)) throw UsageError("the copy-bandwidth buffers need at least 64 KiB (asked: " + std::to_string(bytes) + " bytes)");
  if (min_bytes > bytes || min_bytes < 256) throw UsageError("the copy-bandwidth fallback size must lie in [256 bytes, the size asked]");
}

CopyBandwidth measure_copy_bandwidth(Device& device, const CopyBandwidthOptions& o) {
  o.check();
  require_timestamps(device.info());
  CopyBandwidth out;
  out.requested_bytes = o.bytes;
  out.warmup = o.warmup;
  // Limits the device states, before asking it.
  VkPhysicalDeviceMaintenance3Properties m3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props.pNext = &m3;
  vkGetPhysicalDeviceProperties2(device.physical(), &props);
  VkPhysicalDeviceMemoryProperties mem{};
  vkGetPhysicalDeviceMemoryProperties(device.physical(), &mem);
  VkDeviceSize largest_heap = 0;
  for (uint32_t h = 0; h < mem.memoryHeapCount; ++h)
    if (mem.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) largest_heap = std::max(largest_heap, mem.memoryHeaps[h].size);
  const CopySizePlan plan = plan_copy_size(o.bytes, m3.maxMemoryAllocationSize, largest_heap);
  uint64_t bytes = plan.bytes;
  out.reduced_because = plan.reduced_because;

  // Then what it can actually allocate.
  std::optional<Pair> buffers;
  for (;;) {
    if (bytes < o.min_bytes)
      throw DeviceError("out of device memory for the copy-bandwidth measurement: not even two buffers of " +
                        mib(o.min_bytes) + " could be allocated on " + device.info().name);
    buffers = try_allocate_pair(device, bytes);
    if (buffers) break;
    out.reduced_because = "out of device memory for two buffers of " + mib(bytes);
    bytes = aligned(bytes / 2);
  }
  out.bytes = bytes;

  const uint32_t copies = o.warmup + o.copies;
  TimestampPool pool(device, copies + 1, "copy_bandwidth.timestamps");
  device.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        pool.reset(cmd);
        // Both buffers written once, untimed, so no copy pays for first-touch page allocation.
        vkCmdFillBuffer(cmd, buffers->src.buffer.get(), 0, VK_WHOLE_SIZE, 0x3f800000u);
        vkCmdFillBuffer(cmd, buffers->dst.buffer.get(), 0, VK_WHOLE_SIZE, 0u);
        CommandStream(cmd).full_barrier();
        pool.write(cmd);
        const VkBufferCopy region{0, 0, bytes};
        for (uint32_t k = 0; k < copies; ++k) {
          vkCmdCopyBuffer(cmd, buffers->src.buffer.get(), buffers->dst.buffer.get(), 1, &region);
          pool.write(cmd);  // full barriers: copy k + 1 starts after copy k (and its write) ended
        }
      },
      "copy-bandwidth measurement");
  const std::vector<uint64_t> ticks = pool.read_ticks();
  for (uint32_t k = o.warmup; k < copies; ++k) {
    try {
      out.samples_ms.push_back(pool.interval_ns(ticks[k], ticks[k + 1]) * 1e-6);
    } catch (const DeviceError& e) {
      throw DeviceError(std::string("copy-bandwidth measurement: ") + e.what());
    }
  }
  std::vector<double> sorted = out.samples_ms;
  std::sort(sorted.begin(), sorted.end());
  out.median_ms = quantile_sorted(sorted, 0.5);
  out.bytes_per_s = 2.0 * static_cast<double>(bytes) / (out.median_ms * 1e-3);
  return out;
}

}  // namespace vsgl
