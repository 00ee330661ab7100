#include "harness/visibility/ism_settings.hpp"

#include <bit>
#include <cmath>

#include "harness/core/error.hpp"

namespace vsgl {
namespace {

std::string bytes_text(uint64_t bytes) { return std::to_string(bytes) + " bytes"; }

}  // namespace

uint32_t ism_level_count(uint32_t side) { return static_cast<uint32_t>(std::bit_width(side)); }

uint32_t ism_level_offset(uint32_t side, uint32_t level) {
  uint32_t offset = 0;
  for (uint32_t l = 0; l < level; ++l) offset += (side >> l) * (side >> l);
  return offset;
}

uint32_t ism_map_stride(uint32_t side) { return ism_level_offset(side, ism_level_count(side)); }

gpu::IsmParams ism_params(const IsmSettings& s, uint32_t point_count, uint32_t map_count) {
  if (s.side < 2 || s.side > kIsmMaxSide || !std::has_single_bit(s.side))
    throw InputError("imperfect shadow maps: the side " + std::to_string(s.side) + " is not a power of two in [2, " +
                     std::to_string(kIsmMaxSide) + "]");
  if (map_count == 0) throw InputError("imperfect shadow maps: no maps to build");
  if (s.points_per_map == 0) throw InputError("imperfect shadow maps: 0 points per map");
  if (s.points_per_map > point_count)
    throw InputError("imperfect shadow maps: " + std::to_string(s.points_per_map) + " points per map, but only " +
                     std::to_string(point_count) + " points were sampled");
  if (!(s.depth_bias >= 0.0f && s.depth_bias < 1.0f))
    throw InputError("imperfect shadow maps: the depth bias must lie in [0, 1)");
  if (!(s.normal_offset >= 0.0f) || !std::isfinite(s.normal_offset))
    throw InputError("imperfect shadow maps: the normal offset must be finite and not negative");
  if (s.pcf_radius > kIsmMaxPcfRadius)
    throw InputError("imperfect shadow maps: a PCF radius of " + std::to_string(s.pcf_radius) + " is above " +
                     std::to_string(kIsmMaxPcfRadius));
  gpu::IsmParams p{};
  p.side = s.side;
  p.map_count = map_count;
  p.points_per_map = s.points_per_map;
  p.map_stride = ism_map_stride(s.side);
  p.point_count = point_count;
  p.point_stride = point_count / s.points_per_map;
  p.depth_bias = s.depth_bias;
  p.normal_offset = s.normal_offset;
  p.pcf_radius = s.pcf_radius;
  return p;
}

void require_ism_fits(const DeviceLimits& limits, const gpu::IsmParams& p, const std::string& device_name) {
  const std::string what = "imperfect shadow maps (" + std::to_string(p.map_count) + " maps of " +
                           std::to_string(p.side) + "^2, " + std::to_string(p.point_count) + " points)";
  const auto refuse = [&](const std::string& need, uint64_t value, const std::string& limit) {
    throw DeviceLimitError(device_name + " cannot hold the " + what + ": " + need + " where the device allows " +
                           std::to_string(value) + " (" + limit + ")");
  };
  const uint64_t map_bytes = uint64_t{p.map_count} * p.map_stride * sizeof(uint32_t);
  const uint64_t point_bytes = uint64_t{p.point_count} * sizeof(gpu::vec4);
  const uint64_t origin_bytes = uint64_t{p.map_count} * sizeof(gpu::IsmOrigin);
  for (const auto& [name, bytes] : {std::pair<const char*, uint64_t>{"the maps", map_bytes},
                                    {"the points", point_bytes},
                                    {"the origins", origin_bytes}}) {
    if (bytes > limits.storage_buffer_range)
      refuse(std::string(name) + " need " + bytes_text(bytes) + " in one binding", limits.storage_buffer_range,
             "maxStorageBufferRange");
    if (limits.max_memory_allocation_size > 0 && bytes > limits.max_memory_allocation_size)
      refuse(std::string(name) + " need " + bytes_text(bytes) + " in one allocation", limits.max_memory_allocation_size,
             "maxMemoryAllocationSize");
  }
  if (p.map_count > limits.workgroup_count[1])
    refuse("one dispatch row per map, " + std::to_string(p.map_count), limits.workgroup_count[1],
           "maxComputeWorkGroupCount[1]");
  const uint64_t widest = std::max<uint64_t>(p.points_per_map, uint64_t{p.side} * p.side);
  const uint64_t groups = (widest + gpu::kIsmGroupSize - 1) / gpu::kIsmGroupSize;
  if (groups > limits.workgroup_count[0])
    refuse(std::to_string(groups) + " groups of " + std::to_string(gpu::kIsmGroupSize) + " per map",
           limits.workgroup_count[0], "maxComputeWorkGroupCount[0]");
}

}  // namespace vsgl
