// The imperfect shadow maps' parameters and layout (harness/visibility/ism_settings.hpp, DESIGN.md
// §8a.2): the pyramid's offsets, the subsets the maps take, the refusals of unusable settings, and
// the check against the device's limits, which names the limit.
#include <gtest/gtest.h>

#include <string>

#include "harness/core/error.hpp"
#include "harness/visibility/ism_settings.hpp"

namespace vsgl {
namespace {

TEST(IsmSettings, ThePyramidOfA64MapIsItsLevelsOneAfterAnother) {
  EXPECT_EQ(ism_level_count(64), 7u);
  const uint32_t expected[] = {0, 4096, 5120, 5376, 5440, 5456, 5460, 5461};
  for (uint32_t l = 0; l <= 7; ++l) EXPECT_EQ(ism_level_offset(64, l), expected[l]) << "level " << l;
  EXPECT_EQ(ism_map_stride(64), 5461u);
  EXPECT_EQ(ism_map_stride(2), 5u);
}

TEST(IsmSettings, MapsTakeDisjointInterleavedSubsetsWhereThereArePointsEnough) {
  IsmSettings s;
  const gpu::IsmParams p = ism_params(s, 4 * s.points_per_map + 3, 4);
  EXPECT_EQ(p.side, 64u);
  EXPECT_EQ(p.map_stride, 5461u);
  EXPECT_EQ(p.point_stride, 4u);  // map m: m, m + 4, m + 8, ...: four disjoint subsets
  EXPECT_EQ(p.points_per_map, gpu::kIsmDefaultPointsPerMap);
  EXPECT_EQ(p.pcf_radius, 1u);
  EXPECT_EQ(ism_params(s, s.points_per_map, 10).point_stride, 1u);  // all maps share the points
}

TEST(IsmSettings, RefusesUnusableSettings) {
  const auto params = [](IsmSettings s, uint32_t points = 100000, uint32_t maps = 4) {
    return ism_params(s, points, maps);
  };
  IsmSettings s;
  for (uint32_t side : {0u, 1u, 48u, 8192u}) {
    s.side = side;
    EXPECT_THROW(params(s), InputError) << side;
  }
  s = {};
  EXPECT_THROW(params(s, 100, 4), InputError);  // fewer points than one map takes
  EXPECT_THROW(params(s, 100000, 0), InputError);
  s.points_per_map = 0;
  EXPECT_THROW(params(s), InputError);
  s = {};
  s.depth_bias = 1.0f;
  EXPECT_THROW(params(s), InputError);
  s.depth_bias = -0.1f;
  EXPECT_THROW(params(s), InputError);
  s = {};
  s.normal_offset = -1.0f;
  EXPECT_THROW(params(s), InputError);
  s = {};
  s.pcf_radius = kIsmMaxPcfRadius + 1;
  EXPECT_THROW(params(s), InputError);
}

// A device that binds 256 MiB holds a thousand default maps and their 8 million points (128 MiB);
// the check names the limit a size breaks.
TEST(IsmSettings, TheDeviceLimitCheckNamesTheLimit) {
  DeviceLimits limits;
  limits.storage_buffer_range = 1u << 28;
  limits.max_memory_allocation_size = uint64_t{1} << 31;
  limits.workgroup_count = {65535, 65535, 65535};
  const gpu::IsmParams p = ism_params(IsmSettings{}, 1024 * gpu::kIsmDefaultPointsPerMap, 1024);
  EXPECT_NO_THROW(require_ism_fits(limits, p, "device"));
  const auto message = [&](const DeviceLimits& l, const gpu::IsmParams& q) -> std::string {
    try {
      require_ism_fits(l, q, "device");
    } catch (const DeviceLimitError& e) {
      return e.what();
    }
    return "";
  };
  DeviceLimits small = limits;
  small.storage_buffer_range = 1u << 20;  // 1 MiB: not the 22 MB of the maps
  EXPECT_NE(message(small, p).find("maxStorageBufferRange"), std::string::npos) << message(small, p);
  small = limits;
  small.max_memory_allocation_size = 1u << 20;
  EXPECT_NE(message(small, p).find("maxMemoryAllocationSize"), std::string::npos) << message(small, p);
  small = limits;
  small.workgroup_count[1] = 1000;
  EXPECT_NE(message(small, p).find("maxComputeWorkGroupCount[1]"), std::string::npos) << message(small, p);
  small = limits;
  small.workgroup_count[0] = 100;  // 8192 points per map need 128 groups of 64
  EXPECT_NE(message(small, p).find("maxComputeWorkGroupCount[0]"), std::string::npos) << message(small, p);
}

}  // namespace
}  // namespace vsgl
