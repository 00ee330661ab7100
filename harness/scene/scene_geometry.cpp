#include "harness/scene/scene_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "harness/core/portable_float.hpp"

namespace vsgl {
namespace {

SceneVertex make_vertex(glm::vec3 position, glm::vec3 normal, const SurfaceMaterial& m, glm::vec2 uv = glm::vec2(0.0f),
                        glm::vec4 tangent = glm::vec4(0.0f)) {
  return SceneVertex{position, normal, m.diffuse, m.specular, m.roughness, uv, tangent, m.material};
}

uint32_t next_index(const SceneMesh& mesh) { return static_cast<uint32_t>(mesh.vertices.size()); }

// Appends the quad a, b, c, d (counter-clockwise seen from its front) as two triangles.
void push_quad_indices(SceneMesh& mesh, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
}

uint32_t cells_for(float length, float max_cell) {
  return std::max(1u, static_cast<uint32_t>(std::ceil(length / max_cell - 1e-4f)));
}

// Closest point to p on triangle abc, by the Voronoi regions of its vertices, edges and face
// (the standard construction of Ericson, "Real-Time Collision Detection", §5.1.5).
glm::vec3 closest_point_on_triangle(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return a;
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const float denom = 1.0f / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// The quad of add_quad, with its texture coordinates either along (edge_a, edge_b) or, with
// uv_swapped, along (edge_b, edge_a): the winding (and so the normal) stays cross(edge_a, edge_b).
void add_quad_mapped(SceneMesh& mesh, glm::vec3 origin, glm::vec3 edge_a, glm::vec3 edge_b,
                     const SurfaceMaterial& material, uint32_t cells_a, uint32_t cells_b, bool uv_swapped) {
  if (cells_a == 0 || cells_b == 0) throw std::logic_error("add_quad: zero cells");
  const glm::vec3 normal = glm::normalize(glm::cross(edge_a, edge_b));
  const glm::vec3 da = edge_a / static_cast<float>(cells_a);
  const glm::vec3 db = edge_b / static_cast<float>(cells_b);
  const float len_a = glm::length(edge_a), len_b = glm::length(edge_b);
  // The tangent follows +u. Unswapped, cross(normal, edge_a) points along +edge_b = +v (w = +1);
  // swapped, +u is edge_b and cross(normal, edge_b) points along -edge_a = -v (w = -1).
  const glm::vec4 tangent = uv_swapped ? glm::vec4(edge_b / len_b, -1.0f) : glm::vec4(edge_a / len_a, 1.0f);
  auto uv = [&](uint32_t i, uint32_t j) {
    const glm::vec2 ab(len_a * static_cast<float>(i) / static_cast<float>(cells_a),
                       len_b * static_cast<float>(j) / static_cast<float>(cells_b));
    return uv_swapped ? glm::vec2(ab.y, ab.x) : ab;
  };
  for (uint32_t j = 0; j < cells_b; ++j) {
    for (uint32_t i = 0; i < cells_a; ++i) {
      // Corners from the origin (not accumulated) so that neighbouring cells share exact edges.
      const glm::vec3 p00 = origin + da * static_cast<float>(i) + db * static_cast<float>(j);
      const glm::vec3 p10 = origin + da * static_cast<float>(i + 1) + db * static_cast<float>(j);
      const glm::vec3 p11 = origin + da * static_cast<float>(i + 1) + db * static_cast<float>(j + 1);
      const glm::vec3 p01 = origin + da * static_cast<float>(i) + db * static_cast<float>(j + 1);
      const uint32_t first = next_index(mesh);
      mesh.vertices.push_back(make_vertex(p00, normal, material, uv(i, j), tangent));
      mesh.vertices.push_back(make_vertex(p10, normal, material, uv(i + 1, j), tangent));
      mesh.vertices.push_back(make_vertex(p11, normal, material, uv(i + 1, j + 1), tangent));
      mesh.vertices.push_back(make_vertex(p01, normal, material, uv(i, j + 1), tangent));
      // cross(da, db) is the normal: (p00, p10, p11) turns counter-clockwise around it.
      push_quad_indices(mesh, first, first + 1, first + 2, first + 3);
    }
  }
}

}  // namespace

void add_quad(SceneMesh& mesh, glm::vec3 origin, glm::vec3 edge_u, glm::vec3 edge_v,
              const SurfaceMaterial& material, uint32_t cells_u, uint32_t cells_v) {
  add_quad_mapped(mesh, origin, edge_u, edge_v, material, cells_u, cells_v, false);
}

void add_axis_rect(SceneMesh& mesh, glm::vec3 lo, glm::vec3 hi, glm::vec3 normal,
                   const SurfaceMaterial& material, float max_cell) {
  int axis = -1;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(normal[k]) == 1.0f) axis = k;
  }
  if (axis < 0 || glm::dot(normal, normal) != 1.0f) {
    throw std::logic_error("add_axis_rect: normal must be a signed unit axis");
  }
  if (lo[axis] != hi[axis]) throw std::logic_error("add_axis_rect: rectangle not flat along its normal");
  // e_i x e_j = e_k for the cyclic order (i, j, k): with the normal along +k the edges go
  // along i then j; along -k they are swapped.
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  glm::vec3 edge_i(0.0f), edge_j(0.0f);
  edge_i[i] = hi[i] - lo[i];
  edge_j[j] = hi[j] - lo[j];
  if (edge_i[i] <= 0.0f || edge_j[j] <= 0.0f) throw std::logic_error("add_axis_rect: empty rectangle");
  const uint32_t cells_i = cells_for(edge_i[i], max_cell), cells_j = cells_for(edge_j[j], max_cell);
  // Texture u runs along x, except on faces across x (there along z); v along the remaining axis
  // (up on walls). So a pattern has one orientation on every wall and floor of a scene.
  const int u_axis = axis == 0 ? 2 : 0;
  if (normal[axis] > 0.0f) {
    add_quad_mapped(mesh, lo, edge_i, edge_j, material, cells_i, cells_j, u_axis != i);
  } else {
    add_quad_mapped(mesh, lo, edge_j, edge_i, material, cells_j, cells_i, u_axis != j);
  }
}

void add_box(SceneMesh& mesh, glm::vec3 lo, glm::vec3 hi, const SurfaceMaterial& material,
             uint32_t faces) {
  const float whole = std::numeric_limits<float>::infinity();  // one cell per face
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      if ((faces & (1u << (2 * axis + side))) == 0) continue;
      glm::vec3 face_lo = lo, face_hi = hi, normal(0.0f);
      const float plane = side == 0 ? lo[axis] : hi[axis];
      face_lo[axis] = face_hi[axis] = plane;
      normal[axis] = side == 0 ? -1.0f : 1.0f;  // outward
      add_axis_rect(mesh, face_lo, face_hi, normal, material, whole);
    }
  }
}

void add_room(SceneMesh& mesh, glm::vec3 lo, glm::vec3 hi,
              const std::array<SurfaceMaterial, 6>& materials, float max_cell) {
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      glm::vec3 face_lo = lo, face_hi = hi, normal(0.0f);
      const float plane = side == 0 ? lo[axis] : hi[axis];
      face_lo[axis] = face_hi[axis] = plane;
      normal[axis] = side == 0 ? 1.0f : -1.0f;  // inward: the camera is inside
      add_axis_rect(mesh, face_lo, face_hi, normal, materials[static_cast<std::size_t>(2 * axis + side)], max_cell);
    }
  }
}

void add_open_cylinder(SceneMesh& mesh, glm::vec3 base_centre, float radius, float height,
                       uint32_t sides, const SurfaceMaterial& material) {
  if (sides < 3) throw std::logic_error("add_open_cylinder: fewer than 3 sides");
  const glm::vec3 up(0.0f, height, 0.0f);
  const uint32_t first = next_index(mesh);
  // u wraps around a whole number of metres (the circumference rounded, at least 1), so a
  // texture repeating at 1 m meets itself at the seam; v is the height above the base.
  const float u_turn = std::max(1.0f, std::round(2.0f * std::numbers::pi_v<float> * radius));
  // Ring k at angle theta: direction (sin, 0, cos). Its tangent (cos, 0, -sin) crossed with +y
  // is the outward direction, so (bottom k, bottom k+1, top k+1) is counter-clockwise outside;
  // cross(outward, tangent) = +y = +v, handedness +1. Ring `sides` repeats ring 0 at u = u_turn.
  for (uint32_t k = 0; k <= sides; ++k) {
    const uint32_t at = k % sides;
    const float theta = 2.0f * std::numbers::pi_v<float> * static_cast<float>(at) / static_cast<float>(sides);
    const glm::vec3 outward(portable::sin(theta), 0.0f, portable::cos(theta));
    const glm::vec4 tangent(portable::cos(theta), 0.0f, -portable::sin(theta), 1.0f);
    const float u = u_turn * static_cast<float>(k) / static_cast<float>(sides);
    const glm::vec3 bottom = base_centre + radius * outward;
    mesh.vertices.push_back(make_vertex(bottom, outward, material, {u, 0.0f}, tangent));
    mesh.vertices.push_back(make_vertex(bottom + up, outward, material, {u, height}, tangent));
  }
  for (uint32_t k = 0; k < sides; ++k) {
    push_quad_indices(mesh, first + 2 * k, first + 2 * (k + 1), first + 2 * (k + 1) + 1, first + 2 * k + 1);
  }
}

float distance_to_mesh(const SceneMesh& mesh, glm::vec3 p) {
  float best_squared = std::numeric_limits<float>::infinity();
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 q = closest_point_on_triangle(p, mesh.vertices[mesh.indices[t]].position,
                                                  mesh.vertices[mesh.indices[t + 1]].position,
                                                  mesh.vertices[mesh.indices[t + 2]].position);
    const glm::vec3 d = p - q;
    best_squared = std::min(best_squared, glm::dot(d, d));
  }
  return std::sqrt(best_squared);
}

std::optional<RayHit> first_hit(const SceneMesh& mesh, glm::vec3 origin, glm::vec3 direction,
                                float max_distance, float min_distance) {
  std::optional<RayHit> best;
  float best_t = max_distance;
  // Möller–Trumbore: solve origin + t*direction = a + u*(b-a) + v*(c-a) by Cramer's rule.
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.vertices[mesh.indices[t]].position;
    const glm::vec3 e1 = mesh.vertices[mesh.indices[t + 1]].position - a;
    const glm::vec3 e2 = mesh.vertices[mesh.indices[t + 2]].position - a;
    const glm::vec3 pvec = glm::cross(direction, e2);
    const float det = glm::dot(e1, pvec);
    if (std::abs(det) < 1e-12f) continue;  // parallel to the plane (or degenerate)
    const float inv_det = 1.0f / det;
    const glm::vec3 tvec = origin - a;
    const float u = glm::dot(tvec, pvec) * inv_det;
    if (u < 0.0f || u > 1.0f) continue;
    const glm::vec3 qvec = glm::cross(tvec, e1);
    const float v = glm::dot(direction, qvec) * inv_det;
    if (v < 0.0f || u + v > 1.0f) continue;
    const float distance = glm::dot(e2, qvec) * inv_det;
    if (distance > min_distance && distance <= best_t) {
      best_t = distance;
      best = RayHit{distance, static_cast<uint32_t>(t / 3)};
    }
  }
  return best;
}

glm::vec3 triangle_normal(const SceneMesh& mesh, uint32_t triangle) {
  const std::size_t t = std::size_t{triangle} * 3;
  const glm::vec3 a = mesh.vertices[mesh.indices[t]].position;
  const glm::vec3 b = mesh.vertices[mesh.indices[t + 1]].position;
  const glm::vec3 c = mesh.vertices[mesh.indices[t + 2]].position;
  return glm::normalize(glm::cross(b - a, c - a));
}

}  // namespace vsgl
