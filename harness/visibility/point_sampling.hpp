#pragma once
// An area-weighted point sampling of a triangle soup, the scene the imperfect shadow maps splat
// (DESIGN.md §8a.2). Point i of n sits at u_i = (i + xi_i) / n of the cumulative area (one jittered
// stratum each), so a triangle of area fraction f gets within one point of f n, and every
// interleaved subset {k, k + s, k + 2s, ...} the maps take is itself a stratified sample of the
// whole surface. Within its triangle a point is at barycentrics (1 - sqrt(a), sqrt(a)(1 - c),
// sqrt(a) c), uniform in area, with a the stratum's position inside the triangle and c a fresh
// random number. The random numbers come from std::mt19937_64 (its sequence is fixed by the
// standard) converted by hand, so one seed gives the same points on every platform.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "harness/math/surface_point.hpp"

namespace vsgl {

// `count` points on the triangles of `vertices` (3 per triangle, a, b, c), in stratum order.
// Throws InputError for a vertex count that is not a multiple of 3, a non-finite vertex, a soup
// without area, or a count of 0. Triangles without area get no point.
std::vector<SurfacePoint> sample_triangle_soup(const std::vector<glm::vec3>& vertices, uint32_t count, uint64_t seed);

// "fnv1a64:<16 hex>" over every point's position, normal (float bytes) and triangle (uint32 bytes),
// in order: identifies a sampling exactly.
std::string points_content_hash(const std::vector<SurfacePoint>& points);

}  // namespace vsgl
