#pragma once
// GPU timestamps done right (DESIGN.md §9): refuse a queue without valid bits, convert ticks with
// timestampPeriod, subtract under the wrap mask, write after a full barrier so that no earlier
// work leaks into a phase, reset before every use, read 64-bit with wait, and treat a zero or
// negative interval as an error rather than a number.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "harness/vk/unique_handle.hpp"

namespace vsgl {

class Device;

class TimestampPool {
 public:
  TimestampPool(Device& device, uint32_t capacity, const std::string& name);
  TimestampPool(const TimestampPool&) = delete;
  TimestampPool& operator=(const TimestampPool&) = delete;

  // Resets all queries (record before the first write(), outside any render pass).
  void reset(VkCommandBuffer cmd);
  // Full barrier, timestamp, full barrier: the clock is read after all earlier work and before any
  // later work (on every driver, including lazy ones). Returns the query index.
  uint32_t write(VkCommandBuffer cmd);
  uint32_t written() const { return written_; }

  // Waits for and returns the raw ticks of all written queries.
  std::vector<uint64_t> read_ticks() const;

  // end − start in nanoseconds, under the wrap mask. Throws DeviceError for a zero interval or
  // one that can only be a negative interval seen through the wrap (more than half the range).
  double interval_ns(uint64_t start_ticks, uint64_t end_ticks) const;

  double period_ns() const { return period_ns_; }
  uint32_t valid_bits() const { return valid_bits_; }

  static uint64_t mask_for_bits(uint32_t valid_bits);
  // The interval arithmetic alone, so it can be tested without a device.
  static double interval_ns(uint64_t start_ticks, uint64_t end_ticks, uint64_t mask, double period_ns);

 private:
  UniqueHandle<VkQueryPool> pool_;
  VkDevice device_;
  uint32_t capacity_;
  uint32_t written_ = 0;
  uint32_t valid_bits_;
  uint64_t mask_;
  double period_ns_;
  std::string name_;
};

}  // namespace vsgl
