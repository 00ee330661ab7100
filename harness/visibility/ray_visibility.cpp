#include "harness/visibility/ray_visibility.hpp"

#include <algorithm>

#include "harness/core/error.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {
namespace {

void require_at_most(uint64_t asked, uint64_t limit, const char* limit_name, const std::string& what,
                     const std::string& device_name) {
  if (asked > limit)
    throw DeviceLimitError(device_name + " cannot hold " + what + ": " + std::to_string(asked) +
                           " bytes, and the device allows " + std::to_string(limit) + " (" + limit_name + ")");
}

// Each of the two buffers against maxStorageBufferRange and maxMemoryAllocationSize.
void require_each_buffer_fits(const VisibilityLimits& limits, uint64_t node_bytes, uint64_t triangle_bytes,
                              const std::string& device_name) {
  const std::string nodes = "the BVH's node buffer", triangles = "the BVH's triangle buffer";
  require_at_most(node_bytes, limits.storage_buffer_range, "maxStorageBufferRange", nodes, device_name);
  require_at_most(triangle_bytes, limits.storage_buffer_range, "maxStorageBufferRange", triangles, device_name);
  if (limits.max_allocation != 0) {
    require_at_most(node_bytes, limits.max_allocation, "maxMemoryAllocationSize", nodes, device_name);
    require_at_most(triangle_bytes, limits.max_allocation, "maxMemoryAllocationSize", triangles, device_name);
  }
}

}  // namespace

VisibilityLimits visibility_limits(const DeviceInfo& info) {
  VisibilityLimits l;
  l.storage_buffer_range = info.limits.storage_buffer_range;
  l.max_allocation = info.limits.max_memory_allocation_size;
  l.device_local_bytes = info.device_local_bytes;
  l.max_group_count_x = info.limits.workgroup_count[0];
  return l;
}

uint32_t visibility_chunk_queries(const VisibilityLimits& limits) {
  uint64_t chunk = kVisibilityQueriesPerDispatch;
  chunk = std::min<uint64_t>(chunk, limits.storage_buffer_range / sizeof(gpu::SegmentQuery));
  chunk = std::min<uint64_t>(chunk, uint64_t{limits.max_group_count_x} * gpu::kVisibilityGroupSize);
  return static_cast<uint32_t>(chunk);
}

void require_bvh_buffers_fit(const VisibilityLimits& limits, uint64_t node_bytes, uint64_t triangle_bytes,
                             const std::string& device_name) {
  require_each_buffer_fits(limits, node_bytes, triangle_bytes, device_name);
  if (limits.device_local_bytes != 0)
    require_at_most(node_bytes + triangle_bytes, limits.device_local_bytes, "the device-local heap",
                    "the BVH and its triangles", device_name);
}

void require_visibility_buffers_fit(const VisibilityLimits& limits, uint64_t node_bytes, uint64_t triangle_bytes,
                                    const std::string& device_name) {
  require_each_buffer_fits(limits, node_bytes, triangle_bytes, device_name);
  const uint32_t chunk = visibility_chunk_queries(limits);
  if (chunk == 0)
    throw DeviceLimitError(device_name + " cannot bind one segment query (" +
                           std::to_string(sizeof(gpu::SegmentQuery)) + " bytes): the device allows " +
                           std::to_string(limits.storage_buffer_range) + " (maxStorageBufferRange) and " +
                           std::to_string(limits.max_group_count_x) + " groups (maxComputeWorkGroupCount[0])");
  const uint64_t chunk_bytes = uint64_t{chunk} * (sizeof(gpu::SegmentQuery) + sizeof(uint32_t));
  if (limits.device_local_bytes != 0)
    require_at_most(node_bytes + triangle_bytes + chunk_bytes, limits.device_local_bytes, "the device-local heap",
                    "the BVH, its triangles and one dispatch of queries", device_name);
}

RayVisibility::RayVisibility(Device& device, const Bvh& bvh, const TriangleSoup& soup)
    : RayVisibility(device, bvh, soup, visibility_limits(device.info())) {}

RayVisibility::RayVisibility(Device& device, const Bvh& bvh, const TriangleSoup& soup, const VisibilityLimits& limits)
    : device_(device) {
  if (bvh.triangle_order.size() != soup.triangle_count() || bvh.soup_hash != soup_content_hash(soup))
    throw InputError("visibility: the BVH (soup " + bvh.soup_hash + ") was not built over this soup (" +
                     soup_content_hash(soup) + ")");
  if (bvh.depth > gpu::kBvhMaxDepth)
    throw InputError("visibility: the BVH is " + std::to_string(bvh.depth) +
                     " levels deep, more than the traversal's stack holds (kBvhMaxDepth = " +
                     std::to_string(gpu::kBvhMaxDepth) + ")");
  if (bvh.nodes.empty()) return;  // nothing occludes: visible() answers without the GPU
  const std::vector<gpu::BvhTriangle> triangles = bvh_triangles(bvh, soup);
  const uint64_t node_bytes = bvh.nodes.size() * sizeof(gpu::BvhNode);
  const uint64_t triangle_bytes = triangles.size() * sizeof(gpu::BvhTriangle);
  require_visibility_buffers_fit(limits, node_bytes, triangle_bytes, device.info().name);

  node_count_ = static_cast<uint32_t>(bvh.nodes.size());
  chunk_ = visibility_chunk_queries(limits);
  nodes_ = Buffer(device, node_bytes, MemoryUsage::kDeviceLocal, "visibility.nodes");
  triangles_ = Buffer(device, triangle_bytes, MemoryUsage::kDeviceLocal, "visibility.triangles");
  queries_ =
      Buffer(device, uint64_t{chunk_} * sizeof(gpu::SegmentQuery), MemoryUsage::kDeviceLocal, "visibility.queries");
  results_ = Buffer(device, uint64_t{chunk_} * sizeof(uint32_t), MemoryUsage::kDeviceLocal, "visibility.results");
  upload(device, nodes_, bvh.nodes.data(), node_bytes);
  upload(device, triangles_, triangles.data(), triangle_bytes);
  pipeline_.emplace(device, ComputePipelineDesc{"visibility_segments.comp", 4, sizeof(gpu::VisibilityPush),
                                                work_group_size_1d(gpu::kVisibilityGroupSize)});
  set_.emplace(device, *pipeline_, std::initializer_list<BufferBinding>{nodes_, triangles_, queries_, results_},
               "visibility.set");
}

std::vector<uint32_t> RayVisibility::visible(std::span<const gpu::SegmentQuery> queries) {
  std::vector<uint32_t> answers(queries.size(), 1u);
  if (node_count_ == 0) return answers;
  for (std::size_t first = 0; first < queries.size(); first += chunk_) {
    const uint32_t n = static_cast<uint32_t>(std::min<std::size_t>(chunk_, queries.size() - first));
    upload(device_, queries_, queries.data() + first, std::size_t{n} * sizeof(gpu::SegmentQuery));
    const gpu::VisibilityPush push{n, node_count_, 0u, 0u};
    device_.submit_and_wait(
        [&](VkCommandBuffer cmd) {
          CommandStream stream(cmd);
          // The queries were uploaded, and the previous chunk's answers read back, by earlier submissions.
          stream.full_barrier();
          stream.dispatch(*pipeline_, *set_, push, div_up(n, gpu::kVisibilityGroupSize));
        },
        "visibility segments");
    ++dispatches_;
    download(device_, results_, answers.data() + first, std::size_t{n} * sizeof(uint32_t));
  }
  return answers;
}

}  // namespace vsgl
