#pragma once
// Builders for the procedural scenes of DESIGN.md §3 (rectangles, boxes, rooms, open cylinders) and
// brute-force queries on a SceneMesh that the tests use (distance to the surface, ray hits).
// Every builder emits triangles counter-clockwise seen from the side its normals face, so the
// rasterizer's back-face culling keeps exactly the visible side.
#include <array>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "harness/scene/scene.hpp"

namespace vsgl {

struct SurfaceMaterial {
  glm::vec3 diffuse{0.5f};    // diffuse albedo in [0,1]
  glm::vec3 specular{0.04f};  // specular albedo in [0,1]
  float roughness = 0.5f;     // GGX alpha in (0,1]
  // An index into Scene::materials (textures, normal maps; usually MaterialModel::kVertexAlbedo,
  // which modulates the three constants above), or kNoMaterial: the constants as they are.
  uint32_t material = kNoMaterial;
};

// One bit per face of an axis-aligned box, named by the side of the box it lies on.
enum BoxFace : uint32_t {
  kBoxNegX = 1u << 0,
  kBoxPosX = 1u << 1,
  kBoxNegY = 1u << 2,
  kBoxPosY = 1u << 3,
  kBoxNegZ = 1u << 4,
  kBoxPosZ = 1u << 5,
  kBoxAllFaces = 0x3Fu,
};

// The parallelogram origin + s*edge_u + t*edge_v, s,t in [0,1], split into cells_u x cells_v
// quads (smaller triangles rasterize and interpolate better). Its normal is
// normalize(cross(edge_u, edge_v)): pick the edge order so that it points to the seen side.
// Texture coordinates are metres along the edges (u along edge_u, v along edge_v), so a repeating
// texture tiles at 1 m; the tangent is edge_u's direction (handedness +1).
void add_quad(SceneMesh& mesh, glm::vec3 origin, glm::vec3 edge_u, glm::vec3 edge_v,
              const SurfaceMaterial& material, uint32_t cells_u = 1, uint32_t cells_v = 1);

// An axis-aligned rectangle spanning [lo, hi], which must be flat along the axis of `normal`
// (a signed unit axis such as (0,0,-1)); subdivided into cells no larger than max_cell metres.
// Texture coordinates are metres from lo: u along x (along z on faces across x), v along the
// remaining axis, so a pattern keeps one orientation on all walls and floors.
void add_axis_rect(SceneMesh& mesh, glm::vec3 lo, glm::vec3 hi, glm::vec3 normal,
                   const SurfaceMaterial& material, float max_cell);

// A solid box seen from outside: the faces in `faces` (BoxFace bits), normals outward. Leave out
// faces that can never be seen (on the floor, against a wall) to avoid coplanar surfaces.
void add_box(SceneMesh& mesh, glm::vec3 lo, glm::vec3 hi, const SurfaceMaterial& material,
             uint32_t faces = kBoxAllFaces);

// A closed room seen from inside: six inward-facing surfaces, subdivided into cells of at most
// max_cell metres. materials are indexed like the BoxFace bits: the wall on the -x side, the one
// on the +x side, the floor (-y), the ceiling (+y), the -z wall, the +z wall.
void add_room(SceneMesh& mesh, glm::vec3 lo, glm::vec3 hi,
              const std::array<SurfaceMaterial, 6>& materials, float max_cell);

// The side of a vertical cylinder without caps (columns reach from base to capital), with smooth
// outward normals; `sides` >= 3 facets around. Texture coordinates: u around (a whole number of
// metres per turn, the circumference rounded), v the height above the base.
void add_open_cylinder(SceneMesh& mesh, glm::vec3 base_centre, float radius, float height,
                       uint32_t sides, const SurfaceMaterial& material);

// Unsigned distance from p to the nearest triangle of the mesh (brute force over all triangles);
// +infinity for a mesh without triangles.
float distance_to_mesh(const SceneMesh& mesh, glm::vec3 p);

struct RayHit {
  float distance;     // along the (unit) ray direction
  uint32_t triangle;  // index of the triangle: its vertices are indices[3*triangle + 0..2]
};

// The nearest triangle hit by the ray origin + t*direction, t in (min_distance, max_distance],
// whichever side faces the ray (brute force). direction must be a unit vector.
std::optional<RayHit> first_hit(const SceneMesh& mesh, glm::vec3 origin, glm::vec3 direction,
                                float max_distance, float min_distance = 1e-4f);

// normalize(cross(b - a, c - a)) of triangle `triangle`: the side its winding makes the front.
glm::vec3 triangle_normal(const SceneMesh& mesh, uint32_t triangle);

}  // namespace vsgl
