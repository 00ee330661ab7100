#pragma once
// Random triangle soups and segments for the visibility tests (DESIGN.md §8a.1), with the cases a
// traversal gets wrong first: axis-aligned triangles on shared planes (flat boxes), triangles
// sharing an edge, degenerate triangles, and segments through an edge point or a vertex, along an
// axis (a delta with zero components), in a triangle's plane, and ending on a triangle.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "harness/visibility/triangle_soup.hpp"

namespace vsgl::test {

inline TriangleSoup random_soup(uint32_t seed, uint32_t triangles) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> centre(-10.0f, 10.0f);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_real_distribution<float> log_size(-3.0f, 1.5f);
  TriangleSoup soup;
  for (uint32_t k = 0; k < triangles; ++k) {
    const glm::vec3 c(centre(rng), centre(rng), centre(rng));
    const float size = std::exp(log_size(rng));
    glm::vec3 v[3];
    for (glm::vec3& p : v) p = c + size * glm::vec3(unit(rng), unit(rng), unit(rng));
    if (k % 5 == 1) {  // axis-aligned, on one of a few shared planes
      const int axis = static_cast<int>(k / 5 % 3);
      const float plane = std::round(c[axis] / 4.0f) * 4.0f;
      for (glm::vec3& p : v) p[axis] = plane;
    } else if (k % 7 == 2 && k > 0) {  // shares an edge with the previous triangle
      v[0] = soup.vertices[3 * (k - 1)];
      v[1] = soup.vertices[3 * (k - 1) + 1];
    } else if (k % 53 == 3) {  // degenerate: its corners on a line
      v[2] = v[0] + 2.0f * (v[1] - v[0]);
    }
    soup.vertices.insert(soup.vertices.end(), v, v + 3);
  }
  return soup;
}

struct TestSegment {
  glm::vec3 from;
  glm::vec3 to;
  float epsilon;
};

inline std::vector<TestSegment> random_segments(const TriangleSoup& soup, uint32_t seed, uint32_t count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coord(-12.0f, 12.0f);
  std::uniform_real_distribution<float> fraction(0.0f, 1.0f);
  std::uniform_int_distribution<std::size_t> pick(0, soup.triangle_count() - 1);
  const auto point = [&] { return glm::vec3(coord(rng), coord(rng), coord(rng)); };
  std::vector<TestSegment> out;
  for (uint32_t i = 0; i < count; ++i) {
    const std::size_t t = pick(rng);
    const glm::vec3 v0 = soup.vertices[3 * t], v1 = soup.vertices[3 * t + 1], v2 = soup.vertices[3 * t + 2];
    const float epsilon = i % 3 == 0 ? 0.0f : i % 3 == 1 ? 1e-4f : 1e-2f;
    glm::vec3 from = point(), to = point();
    switch (i % 6) {
      case 1: {  // through a point of an edge, at its middle
        const float s = fraction(rng);
        const glm::vec3 on_edge = i % 12 == 1 ? v0 + s * (v1 - v0) : v2 + s * (v0 - v2);
        to = 2.0f * on_edge - from;
        break;
      }
      case 2:  // through a vertex
        to = 2.0f * v1 - from;
        break;
      case 3: {  // along an axis: two coordinates of from and to equal
        const int axis = static_cast<int>(i / 6 % 3);
        const glm::vec3 inside = (v0 + v1 + v2) / 3.0f;
        from = inside;
        to = inside;
        from[axis] = coord(rng);
        to[axis] = coord(rng);
        break;
      }
      case 4: {  // from a point on the triangle (a light on a surface)
        float a = fraction(rng), b = fraction(rng);
        if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
        from = v0 + a * (v1 - v0) + b * (v2 - v0);
        break;
      }
      case 5:  // in the triangle's plane
        from = v0 + 3.0f * (v1 - v0) - 1.0f * (v2 - v0);
        to = v0 - 2.0f * (v1 - v0) + 2.0f * (v2 - v0);
        break;
      default: break;
    }
    out.push_back({from, to, epsilon});
  }
  return out;
}

}  // namespace vsgl::test
