#include "harness/visibility/point_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "harness/core/content_hash.hpp"
#include "harness/core/error.hpp"

namespace vsgl {
namespace {

// A double in [0, 1) from the top 53 bits of one draw (not std::uniform_real_distribution, whose
// algorithm differs between standard libraries).
double unit_double(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

glm::dvec3 vertex(const std::vector<glm::vec3>& vertices, std::size_t i) { return glm::dvec3(vertices[i]); }

}  // namespace

std::vector<SurfacePoint> sample_triangle_soup(const std::vector<glm::vec3>& vertices, uint32_t count, uint64_t seed) {
  if (vertices.size() % 3 != 0)
    throw InputError("point sampling: " + std::to_string(vertices.size()) +
                     " vertices is not a whole number of triangles (3 each)");
  if (count == 0) throw InputError("point sampling: asked for 0 points");
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (!std::isfinite(vertices[i].x) || !std::isfinite(vertices[i].y) || !std::isfinite(vertices[i].z))
      throw InputError("point sampling: vertex " + std::to_string(i) + " is not finite");
  const std::size_t triangles = vertices.size() / 3;
  // cumulative[k] = area of triangles 0..k-1, in double so that a large soup's sum keeps its strata.
  std::vector<double> cumulative(triangles + 1, 0.0);
  std::vector<glm::vec3> normals(triangles);
  std::size_t last_with_area = 0;
  for (std::size_t k = 0; k < triangles; ++k) {
    const glm::dvec3 a = vertex(vertices, 3 * k);
    const glm::dvec3 e = glm::cross(vertex(vertices, 3 * k + 1) - a, vertex(vertices, 3 * k + 2) - a);
    const double twice_area = glm::length(e);
    cumulative[k + 1] = cumulative[k] + 0.5 * twice_area;
    if (twice_area > 0.0) {
      normals[k] = glm::vec3(e / twice_area);
      last_with_area = k;
    }
  }
  const double total = cumulative.back();
  if (!(total > 0.0)) throw InputError("point sampling: the triangles have no area");

  std::mt19937_64 rng(seed);
  std::vector<SurfacePoint> points(count);
  for (uint32_t i = 0; i < count; ++i) {
    const double target = (static_cast<double>(i) + unit_double(rng)) / static_cast<double>(count) * total;
    // The triangle whose cumulative-area interval holds the target; one without area has an empty
    // interval and is never found.
    std::size_t k = static_cast<std::size_t>(std::upper_bound(cumulative.begin() + 1, cumulative.end(), target) -
                                             (cumulative.begin() + 1));
    k = std::min(k, last_with_area);
    const double area = cumulative[k + 1] - cumulative[k];
    const double along = std::clamp((target - cumulative[k]) / area, 0.0, 1.0);
    const double s = std::sqrt(along);
    const double c = unit_double(rng);
    const glm::dvec3 p = (1.0 - s) * vertex(vertices, 3 * k) + s * (1.0 - c) * vertex(vertices, 3 * k + 1) +
                         s * c * vertex(vertices, 3 * k + 2);
    points[i] = SurfacePoint{glm::vec3(p), normals[k], static_cast<uint32_t>(k)};
  }
  return points;
}

std::string points_content_hash(const std::vector<SurfacePoint>& points) {
  Fnv1a64 h;
  for (const SurfacePoint& point : points) {
    h.add(&point.position, sizeof point.position);
    h.add(&point.normal, sizeof point.normal);
    h.add(&point.triangle, sizeof point.triangle);
  }
  return h.text();
}

}  // namespace vsgl
