#pragma once
// Exact visibility of segments on the GPU (DESIGN.md §8a.1): a BVH and its soup uploaded once,
// then batches of segment queries answered by kernels/visibility_segments.comp, 1 visible / 0
// occluded, answer for answer what segment_occluded (bvh.hpp) gives on the CPU.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "harness/visibility/bvh.hpp"
#include "harness/vk/buffer.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "kernels/include/interface/visibility.h"

namespace vsgl {

class Device;
struct DeviceInfo;

// At most this many queries per dispatch, one submission each. A query visits O(log n) nodes
// (a few hundred box and triangle tests for a scene of 10^5 triangles), so a dispatch on lavapipe
// takes about a second on 2 loaded cores (a CPU driver has no watchdog) and a discrete GPU a few
// ms, far below the 2 s a Windows driver allows one submission (TDR).
inline constexpr uint32_t kVisibilityQueriesPerDispatch = uint32_t{1} << 16;

// The device's limits the upload is checked against; a test passes smaller ones.
struct VisibilityLimits {
  uint64_t storage_buffer_range = 0;  // maxStorageBufferRange: each buffer is bound whole
  uint64_t max_allocation = 0;        // maxMemoryAllocationSize: one allocation per buffer (0: not known)
  uint64_t device_local_bytes = 0;    // the device-local heap, for all four buffers (0: not known)
  uint32_t max_group_count_x = 0;     // maxComputeWorkGroupCount[0]
};
VisibilityLimits visibility_limits(const DeviceInfo& info);

// Queries per dispatch under `limits`: kVisibilityQueriesPerDispatch, or fewer where the query
// buffer's range or the group count allows fewer; 0 where not one query fits.
uint32_t visibility_chunk_queries(const VisibilityLimits& limits);

// Throws DeviceLimitError, naming the device, the buffer, the limit, its value and the bytes asked,
// where the node or triangle buffer exceeds maxStorageBufferRange or maxMemoryAllocationSize, or
// the two together the device-local heap: the check of a kernel that binds the BVH and makes its
// own segments (the shading pass's exact visibility, DESIGN.md §8.1).
void require_bvh_buffers_fit(const VisibilityLimits& limits, uint64_t node_bytes, uint64_t triangle_bytes,
                             const std::string& device_name);
// The same for RayVisibility: DeviceLimitError where the node or triangle buffer exceeds
// maxStorageBufferRange or maxMemoryAllocationSize, not one query fits a dispatch, or the four
// buffers together exceed the device-local heap.
void require_visibility_buffers_fit(const VisibilityLimits& limits, uint64_t node_bytes, uint64_t triangle_bytes,
                                    const std::string& device_name);

class RayVisibility {
 public:
  // Checks the soup is the one the BVH was built over (its content hash; InputError otherwise),
  // the BVH's depth against kBvhMaxDepth (InputError), then the buffers against `limits` (default:
  // the device's), and only then allocates and uploads: nothing is created when a check fails.
  RayVisibility(Device& device, const Bvh& bvh, const TriangleSoup& soup);
  RayVisibility(Device& device, const Bvh& bvh, const TriangleSoup& soup, const VisibilityLimits& limits);

  // One answer per query, in order: 1 visible, 0 occluded. An empty BVH answers 1 everywhere
  // without a dispatch.
  std::vector<uint32_t> visible(std::span<const gpu::SegmentQuery> queries);

  uint32_t queries_per_dispatch() const { return chunk_; }
  uint64_t dispatch_count() const { return dispatches_; }

 private:
  Device& device_;
  uint32_t node_count_ = 0;
  uint32_t chunk_ = 0;
  Buffer nodes_;
  Buffer triangles_;
  Buffer queries_;
  Buffer results_;
  std::optional<ComputePipeline> pipeline_;
  std::optional<BindingSet> set_;
  uint64_t dispatches_ = 0;
};

}  // namespace vsgl
