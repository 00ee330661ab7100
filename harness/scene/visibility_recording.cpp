#include "harness/scene/visibility_recording.hpp"

#include "harness/visibility/point_sampling.hpp"

namespace vsgl {

VisibilityGeometry scene_visibility_geometry(const Scene& scene, uint32_t points, uint64_t seed) {
  VisibilityGeometry g;
  g.triangle_vertices.reserve(scene.mesh.indices.size());
  for (const uint32_t index : scene.mesh.indices) g.triangle_vertices.push_back(scene.mesh.vertices.at(index).position);
  g.points = sample_triangle_soup(g.triangle_vertices, points, seed);
  g.point_seed = seed;
  return g;
}

}  // namespace vsgl
