#pragma once
// The device's copy bandwidth, measured in the same run as the tables (DESIGN.md §9, "physical
// limit"): vkCmdCopyBuffer between two device-local buffers of `bytes` each (>= 256 MiB by
// default, larger than any cache), a timestamp (TimestampPool: full barriers around it) between
// consecutive copies, `warmup` copies discarded, the median of `copies` timed copies. Each copy
// reads and writes `bytes`, so bandwidth = 2 * bytes / median time: the same read + written count
// the passes' byte model uses (generators/fis/fis_traffic.hpp).
//
// Size: first capped by maxMemoryAllocationSize and by a quarter of the largest device-local heap
// (two buffers beside the run's own), then halved while an allocation runs out of memory, down to
// `min_bytes`; the size used and why it is smaller than asked are recorded, never hidden.
#include <cstdint>
#include <string>
#include <vector>

namespace vsgl {

class Device;

struct CopyBandwidthOptions {
  uint64_t bytes = 256ull << 20;  // per buffer (DESIGN.md §9: >= 256 MiB); tests use a small one
  uint32_t warmup = 2;            // discarded (first touch of the pages, cold TLBs)
  uint32_t copies = 7;            // timed; the median is reported
  uint64_t min_bytes = 1ull << 20;  // the smallest size a fallback may use

  // Throws UsageError for fewer than 1 timed copy, bytes < 64 KiB, or min_bytes > bytes.
  void check() const;
};

struct CopyBandwidth {
  uint64_t requested_bytes = 0;  // per buffer, as asked
  uint64_t bytes = 0;            // per buffer, as used
  std::string reduced_because;   // empty when bytes == requested_bytes
  uint32_t warmup = 0;
  std::vector<double> samples_ms;  // the timed copies
  double median_ms = 0;
  double bytes_per_s = 0;          // 2 * bytes / median (read + written)
};

// The size to try first: `requested` (rounded down to 256 bytes) capped by the allocation limit
// and a quarter of the largest device-local heap (0: no limit known), and why it is smaller.
struct CopySizePlan {
  uint64_t bytes = 0;
  std::string reduced_because;  // empty when not reduced
};
CopySizePlan plan_copy_size(uint64_t requested, uint64_t max_allocation, uint64_t largest_device_local_heap);

// Throws UsageError for bad options, DeviceError ("out of device memory ...") when not even two
// buffers of min_bytes fit, DeviceError for a device without timestamps or a zero interval.
CopyBandwidth measure_copy_bandwidth(Device& device, const CopyBandwidthOptions& options = {});

}  // namespace vsgl
