#pragma once
// The sizes and biases of the imperfect shadow maps (DESIGN.md §8a.2), the parameters the kernels
// read (interface/ism.h) made from them, the layout of a map's pull-push pyramid in the maps
// buffer, and the check of all of it against the device's limits.
#include <cstdint>
#include <string>

#include "harness/core/device_limits.hpp"
#include "kernels/include/interface/ism.h"

namespace vsgl {

struct IsmSettings {
  uint32_t side = gpu::kIsmDefaultSide;                    // texels per side of a map (a power of two)
  uint32_t points_per_map = gpu::kIsmDefaultPointsPerMap;  // points each map splats
  float depth_bias = gpu::kIsmDefaultDepthBias;            // relative to the receiver's distance
  float normal_offset = gpu::kIsmDefaultNormalOffset;      // texel widths along the receiver's normal
  uint32_t pcf_radius = gpu::kIsmDefaultPcfRadius;         // (2r + 1)^2 taps
  bool fill_holes = true;  // false: level 0 as splatted, holes and all (tests look at the holes)
};

inline constexpr uint32_t kIsmMaxSide = 4096;
inline constexpr uint32_t kIsmMaxPcfRadius = 8;

// Levels of a map's pyramid: side x side down to 1 x 1 (log2(side) + 1).
uint32_t ism_level_count(uint32_t side);
// uints from a map's start to level `level` (at most ism_level_count(side)): the sizes of the
// levels before it.
uint32_t ism_level_offset(uint32_t side, uint32_t level);
// uints per map: all its levels.
uint32_t ism_map_stride(uint32_t side);

// The kernels' parameters for `map_count` maps over a shared array of `point_count` points: map m
// splats points (m mod s) + j s, j < points_per_map, with s = point_count / points_per_map, so the
// maps take disjoint subsets where point_count >= map_count points_per_map (as Ritschel et al. do)
// and s different ones otherwise. Throws InputError for a side that is not a power of two in
// [2, kIsmMaxSide], no maps, no points per map or more than there are points, a depth bias outside
// [0, 1), a negative or non-finite normal offset, or a PCF radius above kIsmMaxPcfRadius.
gpu::IsmParams ism_params(const IsmSettings& settings, uint32_t point_count, uint32_t map_count);

// Throws DeviceLimitError naming the limit (maxStorageBufferRange, maxMemoryAllocationSize,
// maxComputeWorkGroupCount) that the maps, the points or the dispatches of `params` exceed on
// the device `device_name` with `limits`.
void require_ism_fits(const DeviceLimits& limits, const gpu::IsmParams& params, const std::string& device_name);

}  // namespace vsgl
