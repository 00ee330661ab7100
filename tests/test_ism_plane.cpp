// An imperfect shadow map of a plane seen from above (harness/visibility/imperfect_shadow_maps.hpp,
// DESIGN.md §8a.2): the map's origin at height h over a square of side 20 h, its axis pointing
// down, the square densely point-sampled. The distance along a direction at disk point p is
// h (1 + |p|^2) / (1 - |p|^2), a function of |p| alone that grows with it, so a texel's exact
// depths lie between its values at the texel's nearest and farthest points from the disk's centre.
//  - The splat: every texel holds the distance of the nearest point that projects into it (found
//    on the CPU with paraboloid.hpp), which lies inside that interval; holes remain (the test is
//    not vacuous).
//  - Pull-push: afterwards no texel is empty, the splatted texels are untouched, and a filled texel
//    is a convex combination of the distances splatted within W texels of it, so it lies inside the
//    exact interval over that window. W = 2^(K+1) - 2 when every aligned 2^K x 2^K block holds a
//    splatted texel (the push reads the parent and its neighbour at each level: 2^(j+1) texels
//    further out at level j, summed over j < K); the density here makes K <= 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_test.hpp"
#include "harness/visibility/imperfect_shadow_maps.hpp"
#include "harness/visibility/paraboloid.hpp"
#include "harness/visibility/point_sampling.hpp"

namespace vsgl {
namespace {

constexpr float kPlaneHeight = 1.0f;
constexpr float kPlaneHalfSide = 10.0f;
// 131072 points on 400 h^2: at the disk's centre a texel (1/256 sr) sees 1.3 points on average, so
// about a quarter of the centre's texels stay empty; away from it a texel's footprint grows as
// 1 / cos^3 and holes become rare.
constexpr uint32_t kPlanePoints = 131072;

class IsmPlaneTest : public test::GpuTest {
 protected:
  static std::vector<glm::vec3> square() {
    const float s = kPlaneHalfSide;
    return {{-s, 0, -s}, {s, 0, -s}, {s, 0, s}, {-s, 0, -s}, {s, 0, s}, {-s, 0, s}};
  }
  static std::vector<SurfacePoint> points() { return sample_triangle_soup(square(), kPlanePoints, 2024); }
  ImperfectShadowMaps build(bool fill_holes) {
    IsmSettings settings;
    settings.points_per_map = kPlanePoints;
    settings.fill_holes = fill_holes;
    return ImperfectShadowMaps(device(), points(), {{glm::vec3(0, kPlaneHeight, 0), glm::vec3(0, -1, 0)}}, settings);
  }
};

// The exact distance to the plane along disk point radius r.
double plane_distance(double r) { return static_cast<double>(kPlaneHeight) * (1.0 + r * r) / (1.0 - r * r); }

// The disk radii nearest to and farthest from the centre over texels [x0, x1] x [y0, y1].
struct RadiusRange {
  double low, high;
};
RadiusRange texel_radii(int x0, int y0, int x1, int y1, uint32_t side) {
  const double step = 2.0 / side;
  const double ax = -1.0 + x0 * step, bx = -1.0 + (x1 + 1) * step;
  const double ay = -1.0 + y0 * step, by = -1.0 + (y1 + 1) * step;
  const double nx = std::clamp(0.0, ax, bx), ny = std::clamp(0.0, ay, by);
  const double fx = std::max(std::abs(ax), std::abs(bx)), fy = std::max(std::abs(ay), std::abs(by));
  return {std::hypot(nx, ny), std::hypot(fx, fy)};
}

TEST_F(IsmPlaneTest, SplatKeepsTheNearestDistanceAndPullPushFillsEveryHoleWithinTheNeighbours) {
  const ImperfectShadowMaps splatted = build(false);
  const ImperfectShadowMaps filled = build(true);
  EXPECT_EQ(splatted.dispatch_count(), 1u);
  EXPECT_EQ(filled.dispatch_count(), 13u);  // splat, 6 pulls, 6 pushes
  const uint32_t side = filled.side();
  ASSERT_EQ(side, 64u);
  const std::vector<float> before = splatted.read_level0();
  const std::vector<float> after = filled.read_level0();
  ASSERT_EQ(before.size(), std::size_t{side} * side);
  ASSERT_EQ(after.size(), before.size());

  // The splat on the CPU: per texel the nearest point that surely projects into it, and the
  // nearest that may (within 1e-3 texel of its edge, where float rounding may choose either).
  const ParaboloidFrame frame = paraboloid_frame(glm::vec3(0, -1, 0));
  const float none = std::numeric_limits<float>::infinity();
  std::vector<float> nearest_sure(before.size(), none), nearest_maybe(before.size(), none);
  for (const SurfacePoint& point : points()) {
    const glm::vec3 v = point.position - glm::vec3(0, kPlaneHeight, 0);
    const float dist = glm::length(v);
    const glm::vec2 p = paraboloid_project(frame.local(v / dist));
    const float e = 1e-3f * 2.0f / static_cast<float>(side);
    const glm::uvec2 t = paraboloid_texel(p, side);
    bool sure = true;
    for (const glm::vec2 jitter : {glm::vec2(-e, -e), glm::vec2(e, -e), glm::vec2(-e, e), glm::vec2(e, e)}) {
      const glm::uvec2 u = paraboloid_texel(p + jitter, side);
      sure = sure && u == t;
      float& maybe = nearest_maybe[u.y * side + u.x];
      maybe = std::min(maybe, dist);
    }
    if (sure) nearest_sure[t.y * side + t.x] = std::min(nearest_sure[t.y * side + t.x], dist);
  }
  // 1e-6 relative: a device's length() may round differently from the CPU's.
  for (std::size_t t = 0; t < before.size(); ++t) {
    ASSERT_LE(before[t], nearest_sure[t] * (1.0f + 1e-6f))
        << "texel " << t << " holds a point farther than the nearest";
    ASSERT_GE(before[t], nearest_maybe[t] * (1.0f - 1e-6f)) << "texel " << t << " holds a distance no point has";
  }

  // The footprint: texels whose four corners look at the square, 5 % inside its edge (the texel's
  // curved image then lies on it), and lie inside the disk.
  const auto on_square = [&](glm::vec2 p) {
    if (glm::dot(p, p) >= 1.0f) return false;
    const glm::vec3 d = frame.world(paraboloid_unproject(p));
    const glm::vec3 hit = glm::vec3(0, kPlaneHeight, 0) + d * (kPlaneHeight / -d.y);
    return std::max(std::abs(hit.x), std::abs(hit.z)) < 0.95f * kPlaneHalfSide;
  };
  const float step = 2.0f / static_cast<float>(side);
  std::vector<char> inside(before.size(), 0);
  uint32_t footprint = 0;
  for (uint32_t y = 0; y < side; ++y)
    for (uint32_t x = 0; x < side; ++x) {
      const glm::vec2 c0(-1.0f + static_cast<float>(x) * step, -1.0f + static_cast<float>(y) * step);
      const bool all = on_square(c0) && on_square(c0 + glm::vec2(step, 0)) && on_square(c0 + glm::vec2(0, step)) &&
                       on_square(c0 + glm::vec2(step, step));
      inside[y * side + x] = all ? 1 : 0;
      footprint += all ? 1 : 0;
    }
  ASSERT_GT(footprint, 2000u) << "the square should fill most of the disk (3217 texels)";

  // The splat. Tolerance 1e-4 relative: a point on a texel's edge may round into its neighbour.
  const auto within = [](double depth, RadiusRange r) {
    return depth >= plane_distance(r.low) * (1.0 - 1e-4) && depth <= plane_distance(r.high) * (1.0 + 1e-4);
  };
  uint32_t holes = 0;
  for (uint32_t y = 0; y < side; ++y)
    for (uint32_t x = 0; x < side; ++x) {
      const std::size_t t = y * side + x;
      if (!inside[t]) continue;
      if (std::isinf(before[t])) {
        ++holes;
        continue;
      }
      const int xi = static_cast<int>(x), yi = static_cast<int>(y);
      EXPECT_TRUE(within(before[t], texel_radii(xi, yi, xi, yi, side)))
          << "texel " << x << "," << y << " holds " << before[t] << ", outside its exact depths";
    }
  EXPECT_GT(holes, footprint / 100) << "too few holes for the fill to be tested";

  // K: the largest level at which an aligned block inside the footprint has no splatted texel.
  const auto block_is_empty = [&](uint32_t bx, uint32_t by, uint32_t size) {
    for (uint32_t y = by; y < by + size; ++y)
      for (uint32_t x = bx; x < bx + size; ++x)
        if (!std::isinf(before[y * side + x])) return false;
    return true;
  };
  const auto rect_is_inside = [&](int x0, int y0, int x1, int y1) {
    if (x0 < 0 || y0 < 0 || x1 >= static_cast<int>(side) || y1 >= static_cast<int>(side)) return false;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        if (!inside[static_cast<std::size_t>(y) * side + static_cast<std::size_t>(x)]) return false;
    return true;
  };
  uint32_t K = 0;
  for (uint32_t size = 1; size <= side; size *= 2)
    for (uint32_t by = 0; by < side; by += size)
      for (uint32_t bx = 0; bx < side; bx += size)
        if (rect_is_inside(static_cast<int>(bx), static_cast<int>(by), static_cast<int>(bx + size - 1),
                           static_cast<int>(by + size - 1)) &&
            block_is_empty(bx, by, size))
          K = std::max(K, static_cast<uint32_t>(std::bit_width(size)));
  ASSERT_LE(K, 2u) << "holes larger than the density should allow";
  const int reach = (1 << (K + 1)) - 2;
  const int block = 1 << K;

  uint32_t filled_checked = 0;
  for (uint32_t y = 0; y < side; ++y)
    for (uint32_t x = 0; x < side; ++x) {
      const std::size_t t = y * side + x;
      ASSERT_FALSE(std::isinf(after[t])) << "texel " << x << "," << y << " still empty after pull-push";
      if (!inside[t]) continue;
      if (!std::isinf(before[t])) {
        ASSERT_EQ(after[t], before[t]) << "pull-push changed splatted texel " << x << "," << y;
        continue;
      }
      // The window, widened to whole blocks of 2^K, must lie in the footprint for the bound to hold.
      const int x0 = static_cast<int>(x) - reach, x1 = static_cast<int>(x) + reach;
      const int y0 = static_cast<int>(y) - reach, y1 = static_cast<int>(y) + reach;
      const auto down = [block](int v) { return v < 0 ? -1 : v / block * block; };
      const auto up = [block](int v) { return (v / block + 1) * block - 1; };
      if (!rect_is_inside(down(x0), down(y0), up(x1), up(y1))) continue;
      ++filled_checked;
      EXPECT_TRUE(within(after[t], texel_radii(x0, y0, x1, y1, side)))
          << "filled texel " << x << "," << y << " holds " << after[t] << ", outside the depths within " << reach
          << " texels";
    }
  EXPECT_GT(filled_checked, holes / 2) << "most holes should be checked against their neighbourhood";
}

}  // namespace
}  // namespace vsgl
