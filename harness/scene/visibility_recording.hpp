#pragma once
// What a capture stores of its scene for visibility (DESIGN.md §3, §8a): the scene mesh's
// triangles in world space and their area-weighted point sampling.
#include <cstdint>

#include "harness/capture/visibility_geometry.hpp"
#include "harness/scene/scene.hpp"

namespace vsgl {

// Throws InputError for a scene without area (no point can be drawn) or `points` of 0.
VisibilityGeometry scene_visibility_geometry(const Scene& scene, uint32_t points, uint64_t seed);

}  // namespace vsgl
