// The point sampling the imperfect shadow maps splat (harness/visibility/point_sampling.hpp,
// DESIGN.md §8a.2): area-weighted and stratified (so are the interleaved subsets the maps take),
// deterministic for a seed, every point on its triangle with the triangle's normal.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "harness/core/error.hpp"
#include "harness/visibility/point_sampling.hpp"

namespace vsgl {
namespace {

// Two triangles in different planes, of areas 0.5 and 1.5 (1 : 3).
std::vector<glm::vec3> one_to_three_soup() {
  return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},   // legs 1 and 1, in z = 0
          {0, 0, 1}, {0, 3, 1}, {0, 0, 2}};  // legs 3 and 1, in x = 0
}

std::vector<uint32_t> points_per_triangle(const std::vector<SurfacePoint>& points, std::size_t triangles,
                                          std::size_t first = 0, std::size_t stride = 1) {
  std::vector<uint32_t> counts(triangles, 0);
  for (std::size_t i = first; i < points.size(); i += stride) ++counts.at(points[i].triangle);
  return counts;
}

// Stratification bounds each triangle's count to less than 2 points from its share f n: of the
// strata u_i in [i / n, (i + 1) / n) of the cumulative area, those inside its interval hold one
// point each, and only the two that straddle its ends are left to chance. An independent sampler
// would miss the share by sqrt(n f (1 - f)), 27 points here, so the bound also fails if the
// stratification is lost.
TEST(IsmPointSampling, EachTriangleGetsItsShareOfTheAreaToWithinOnePoint) {
  const auto points = sample_triangle_soup(one_to_three_soup(), 4000, 7);
  const auto counts = points_per_triangle(points, 2);
  EXPECT_LT(std::abs(counts[0] - 1000.0), 2.0);
  EXPECT_LT(std::abs(counts[1] - 3000.0), 2.0);
  // The subsets a map takes, every 4th point from its own start, are stratified the same way.
  for (std::size_t first = 0; first < 4; ++first) {
    const auto subset = points_per_triangle(points, 2, first, 4);
    EXPECT_LT(std::abs(subset[0] - 250.0), 2.0) << "subset " << first;
    EXPECT_LT(std::abs(subset[1] - 750.0), 2.0) << "subset " << first;
  }
}

TEST(IsmPointSampling, ManyTrianglesOfMixedAreasEachGetTheirShare) {
  std::vector<glm::vec3> soup;
  std::vector<double> areas;
  for (int k = 0; k < 40; ++k) {
    const float s = 0.1f + 0.05f * static_cast<float>((k * 7) % 13);  // legs of 0.1 .. 0.7
    const glm::vec3 a(static_cast<float>(k), 0.0f, 0.0f);
    soup.insert(soup.end(), {a, a + glm::vec3(s, 0, 0), a + glm::vec3(0, s, 0.5f * s)});
    areas.push_back(0.5 * static_cast<double>(s) * static_cast<double>(s) * std::sqrt(1.25));
  }
  soup.insert(soup.end(), {{0, 0, 5}, {1, 0, 5}, {2, 0, 5}});  // no area: no point
  double total = 0;
  for (double a : areas) total += a;
  const uint32_t n = 10007;
  const auto points = sample_triangle_soup(soup, n, 3);
  const auto counts = points_per_triangle(points, 41);
  for (std::size_t k = 0; k < areas.size(); ++k)
    EXPECT_LT(std::abs(counts[k] - areas[k] / total * n), 2.0) << "triangle " << k;
  EXPECT_EQ(counts[40], 0u);
}

TEST(IsmPointSampling, TheSameSeedGivesTheSamePointsAndHashAnotherSeedOthers) {
  const auto a = sample_triangle_soup(one_to_three_soup(), 512, 42);
  const auto b = sample_triangle_soup(one_to_three_soup(), 512, 42);
  const auto c = sample_triangle_soup(one_to_three_soup(), 512, 43);
  ASSERT_EQ(a.size(), 512u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].position, b[i].position) << i;
    ASSERT_EQ(a[i].triangle, b[i].triangle) << i;
  }
  EXPECT_EQ(points_content_hash(a), points_content_hash(b));
  EXPECT_NE(points_content_hash(a), points_content_hash(c));
  EXPECT_NE(a[0].position, c[0].position);
  EXPECT_EQ(points_content_hash(a).rfind("fnv1a64:", 0), 0u);
  EXPECT_EQ(points_content_hash(a).size(), 8u + 16u);
  // One changed bit of one point changes the hash.
  auto d = a;
  d[100].position.x = std::nextafter(d[100].position.x, 10.0f);
  EXPECT_NE(points_content_hash(a), points_content_hash(d));
}

// On its triangle: barycentric coordinates in [0, 1] and no distance from the plane, to float
// rounding of coordinates of size 3 (1e-6 relative); the normal is the unit cross product.
TEST(IsmPointSampling, EveryPointLiesOnItsTriangleWithItsNormal) {
  const auto soup = one_to_three_soup();
  const std::vector<glm::dvec3> normals = {{0, 0, 1}, {1, 0, 0}};  // cross(b - a, c - a)
  const auto points = sample_triangle_soup(soup, 3000, 11);
  glm::dvec3 centroid_sum[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};
  uint32_t counts[2] = {0, 0};
  for (const SurfacePoint& p : points) {
    const std::size_t k = p.triangle;
    ASSERT_LT(k, 2u);
    const glm::dvec3 a(soup[3 * k]), b(soup[3 * k + 1]), c(soup[3 * k + 2]), x(p.position);
    const glm::dvec3 n = normals[k];
    EXPECT_NEAR(glm::dot(x - a, n), 0.0, 4e-6) << "off the plane of triangle " << k;
    // Barycentrics by areas of the sub-triangles, signed along the normal.
    const double whole = glm::dot(glm::cross(b - a, c - a), n);
    const double u = glm::dot(glm::cross(c - b, x - b), n) / whole;
    const double v = glm::dot(glm::cross(a - c, x - c), n) / whole;
    const double w = 1.0 - u - v;
    for (double coordinate : {u, v, w}) {
      EXPECT_GE(coordinate, -4e-6);
      EXPECT_LE(coordinate, 1.0 + 4e-6);
    }
    EXPECT_EQ(glm::dvec3(p.normal), n);
    centroid_sum[k] += x;
    ++counts[k];
  }
  // Uniform in area: each triangle's points average to its centroid. A coordinate of a uniform
  // point has a standard deviation of at most (longest leg) / sqrt(18): 0.24 for the small
  // triangle (750 points), 0.71 for the large (2250), so 4 standard errors of the mean are 0.035 and
  // 0.06 per coordinate. Sampling without the square root (toward the first vertex) would move the
  // mean by ((a - b) + (a - c)) / 12: 0.118 and 0.26.
  for (std::size_t k = 0; k < 2; ++k) {
    const glm::dvec3 centroid =
        (glm::dvec3(soup[3 * k]) + glm::dvec3(soup[3 * k + 1]) + glm::dvec3(soup[3 * k + 2])) / 3.0;
    const glm::dvec3 mean = centroid_sum[k] / static_cast<double>(counts[k]);
    EXPECT_LT(glm::length(mean - centroid), 0.07) << "triangle " << k;
  }
}

TEST(IsmPointSampling, RefusesWhatIsNotATriangleSoupWithArea) {
  EXPECT_THROW(sample_triangle_soup({{0, 0, 0}, {1, 0, 0}}, 10, 1), InputError);
  EXPECT_THROW(sample_triangle_soup({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, 10, 1), InputError);
  EXPECT_THROW(sample_triangle_soup({}, 10, 1), InputError);
  EXPECT_THROW(sample_triangle_soup(one_to_three_soup(), 0, 1), InputError);
  auto bad = one_to_three_soup();
  bad[4].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(sample_triangle_soup(bad, 10, 1), InputError);
}

}  // namespace
}  // namespace vsgl
