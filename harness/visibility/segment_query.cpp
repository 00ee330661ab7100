#include "harness/visibility/segment_query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "harness/core/error.hpp"

namespace vsgl {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Written out, left to right, as bvh_traverse.glsl writes them (GLSL's dot() and cross() leave the
// order to the driver).
float dot3(glm::vec3 a, glm::vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
glm::vec3 cross3(glm::vec3 a, glm::vec3 b) {
  return glm::vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

}  // namespace

gpu::SegmentQuery make_segment_query(glm::vec3 from, glm::vec3 to, float epsilon) {
  if (!std::isfinite(epsilon) || epsilon < 0.0f)
    throw InputError("segment query: the epsilon must be finite and at least 0, not " + std::to_string(epsilon));
  if (!finite(from) || !finite(to)) throw InputError("segment query: an end of the segment is not finite");
  glm::vec3 delta = to - from;
  glm::vec3 inverse(0.0f);
  for (int a = 0; a < 3; ++a) {
    if (std::abs(delta[a]) < std::numeric_limits<float>::min()) delta[a] = 0.0f;
    if (delta[a] != 0.0f) inverse[a] = 1.0f / delta[a];
  }
  const float length = std::sqrt(delta.x * delta.x + delta.y * delta.y + delta.z * delta.z);
  // t_min >= t_max leaves no parameter to hit at: a segment within epsilon of its ends throughout.
  const float t_min = length > 0.0f ? std::min(epsilon / length, 1.0f) : 1.0f;
  gpu::SegmentQuery q;
  q.origin_t_min = glm::vec4(from, t_min);
  q.delta_t_max = glm::vec4(delta, 1.0f - t_min);
  q.inverse_delta = glm::vec4(inverse, 0.0f);
  return q;
}

bool segment_overlaps_box(const gpu::SegmentQuery& q, glm::vec3 lo, glm::vec3 hi) {
  float t_lo = 0.0f;
  float t_hi = 1.0f;
  for (int a = 0; a < 3; ++a) {
    const float o = q.origin_t_min[a];
    const float inverse = q.inverse_delta[a];
    if (inverse == 0.0f) {  // the segment runs inside the slab or outside it throughout
      if (o < lo[a] || o > hi[a]) return false;
      continue;
    }
    const float t0 = (lo[a] - o) * inverse;
    const float t1 = (hi[a] - o) * inverse;
    float near = std::min(t0, t1);
    float far = std::max(t0, t1);
    near = near * (near > 0.0f ? gpu::kBvhSlabShrink : gpu::kBvhSlabGrow);
    far = far * (far > 0.0f ? gpu::kBvhSlabGrow : gpu::kBvhSlabShrink);
    t_lo = std::max(t_lo, near);
    t_hi = std::min(t_hi, far);
  }
  return t_lo <= t_hi;
}

bool segment_hits_triangle(const gpu::SegmentQuery& q, glm::vec3 v0, glm::vec3 v1, glm::vec3 v2) {
  // The triangle's own box first: a node's box holds its triangles' boxes, so this makes every hit
  // one the BVH reaches (segment_overlaps_box is monotone), and the BVH answers as the brute force.
  if (!segment_overlaps_box(q, glm::min(glm::min(v0, v1), v2), glm::max(glm::max(v0, v1), v2))) return false;
  const glm::vec3 origin(q.origin_t_min);
  const glm::vec3 delta(q.delta_t_max);
  const glm::vec3 e1 = v1 - v0;
  const glm::vec3 e2 = v2 - v0;
  const glm::vec3 p = cross3(delta, e2);
  float det = dot3(e1, p);
  if (det == 0.0f) return false;
  const glm::vec3 s = origin - v0;
  float u = dot3(s, p);
  const glm::vec3 r = cross3(s, e1);
  float v = dot3(delta, r);
  float t = dot3(e2, r);
  if (det < 0.0f) {
    det = -det;
    u = -u;
    v = -v;
    t = -t;
  }
  return u >= 0.0f && v >= 0.0f && u + v <= det && t > q.origin_t_min.w * det && t < q.delta_t_max.w * det;
}

}  // namespace vsgl
