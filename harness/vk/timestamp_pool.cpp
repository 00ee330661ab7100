#include "harness/vk/timestamp_pool.hpp"

#include <sstream>

#include "harness/vk/device.hpp"
#include "harness/core/error.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {

uint64_t TimestampPool::mask_for_bits(uint32_t valid_bits) {
  return valid_bits >= 64 ? ~uint64_t{0} : ((uint64_t{1} << valid_bits) - 1);
}

double TimestampPool::interval_ns(uint64_t start, uint64_t end, uint64_t mask, double period_ns) {
  const uint64_t ticks = (end - start) & mask;
  if (ticks == 0)
    throw DeviceError("timestamp interval of zero ticks: the device reported no time for a phase; its timing "
                      "cannot be trusted");
  if (ticks > mask / 2) {
    std::ostringstream os;
    os << "negative timestamp interval (start " << start << ", end " << end << " ticks): timestamps went "
       << "backwards; this device's timing cannot be trusted";
    throw DeviceError(os.str());
  }
  return static_cast<double>(ticks) * period_ns;
}

TimestampPool::TimestampPool(Device& device, uint32_t capacity, const std::string& name)
    : device_(device.get()),
      capacity_(capacity),
      valid_bits_(device.info().timestamp_valid_bits),
      mask_(mask_for_bits(valid_bits_)),
      period_ns_(device.info().timestamp_period_ns),
      name_(name) {
  if (!device.info().timestamps())
    throw DeviceError("device " + device.info().name + " has no timestamp support on its compute queue "
                      "(timestampValidBits = 0 or timestampPeriod = 0): it cannot be timed");
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = capacity;
  VkQueryPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &pool));
  pool_ = UniqueHandle<VkQueryPool>(device_, pool, vkDestroyQueryPool);
  device.set_name(pool, VK_OBJECT_TYPE_QUERY_POOL, name);
}

void TimestampPool::reset(VkCommandBuffer cmd) {
  vkCmdResetQueryPool(cmd, pool_.get(), 0, capacity_);
  written_ = 0;
}

uint32_t TimestampPool::write(VkCommandBuffer cmd) {
  if (written_ >= capacity_) throw std::logic_error("timestamp pool '" + name_ + "' is full");
  VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  b.srcAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  b.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  // Before: nothing earlier may still run when the clock is read.
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &b, 0,
                       nullptr, 0, nullptr);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_.get(), written_);
  // After: nothing later may start before the clock is read. Drivers that resolve a timestamp
  // lazily (lavapipe bins it and reads the clock at its next flush, i.e. the next barrier) would
  // otherwise charge the following phase to this one.
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &b, 0,
                       nullptr, 0, nullptr);
  return written_++;
}

std::vector<uint64_t> TimestampPool::read_ticks() const {
  std::vector<uint64_t> ticks(written_);
  if (written_ == 0) return ticks;
  VK_CHECK(vkGetQueryPoolResults(device_, pool_.get(), 0, written_, ticks.size() * sizeof(uint64_t), ticks.data(),
                                 sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  for (auto& t : ticks) t &= mask_;
  return ticks;
}

double TimestampPool::interval_ns(uint64_t start, uint64_t end) const {
  return interval_ns(start, end, mask_, period_ns_);
}

}  // namespace vsgl
