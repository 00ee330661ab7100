// The procedural scenes of DESIGN.md §3 and the mesh queries the recorder tests rely on. CPU only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "harness/core/error.hpp"
#include "harness/scene/scene.hpp"
#include "harness/scene/scene_geometry.hpp"

namespace vsgl {
namespace {

bool same_vec(glm::vec3 a, glm::vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool same_mesh(const SceneMesh& a, const SceneMesh& b) {
  // SceneVertex is 20 packed 4-byte fields (static_assert in scene.hpp): bytes compare exactly.
  return a.indices == b.indices && a.vertices.size() == b.vertices.size() &&
         std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(SceneVertex)) == 0;
}

// The GGX alpha of a triangle's surface at p (on its plane): the vertex roughness, scaled by the
// material's roughness map (nearest texel of level 0, repeat wrap) as kVertexAlbedo does.
float alpha_at(const Scene& scene, uint32_t triangle, glm::vec3 p) {
  const SceneVertex& a = scene.mesh.vertices[scene.mesh.indices[3 * triangle]];
  const SceneVertex& b = scene.mesh.vertices[scene.mesh.indices[3 * triangle + 1]];
  const SceneVertex& c = scene.mesh.vertices[scene.mesh.indices[3 * triangle + 2]];
  if (a.material == kNoMaterial) return a.roughness;
  // Barycentric coordinates of p in the triangle.
  const glm::vec3 e0 = b.position - a.position, e1 = c.position - a.position, ep = p - a.position;
  const float d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
  const float d20 = glm::dot(ep, e0), d21 = glm::dot(ep, e1), den = d00 * d11 - d01 * d01;
  const float wb = (d11 * d20 - d01 * d21) / den, wc = (d00 * d21 - d01 * d20) / den;
  const glm::vec2 uv = (1.0f - wb - wc) * a.uv + wb * b.uv + wc * c.uv;
  const Material& m = scene.materials[a.material];
  if (m.metallic_roughness_texture < 0) return a.roughness;
  const TextureImage& t = scene.textures[static_cast<std::size_t>(m.metallic_roughness_texture)];
  const auto texel = [](float s, uint32_t n) {
    return static_cast<uint32_t>(std::floor((s - std::floor(s)) * static_cast<float>(n))) % n;
  };
  const std::size_t i = std::size_t{texel(uv.y, t.height)} * t.width + texel(uv.x, t.width);
  const float g = m.roughness_factor * static_cast<float>(t.rgba8[4 * i + 1]) / 255.0f;
  return a.roughness * g * g;
}

// The median GGX alpha over a 41 x 41 grid spanning 40 cm around a ray hit on a flat surface
// (texture coordinates are linear on the hit triangle's plane): the surface's typical gloss,
// whether the hit itself falls on a tile or in a joint.
float alpha_around_hit(const Scene& scene, glm::vec3 origin, glm::vec3 direction, const RayHit& hit) {
  const glm::vec3 p = origin + hit.distance * direction;
  const glm::vec3 n = triangle_normal(scene.mesh, hit.triangle);
  const glm::vec3 s = glm::normalize(glm::cross(n, std::abs(n.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  const glm::vec3 t = glm::cross(n, s);
  std::vector<float> alphas;
  for (int i = -20; i <= 20; ++i)
    for (int j = -20; j <= 20; ++j)
      alphas.push_back(alpha_at(scene, hit.triangle, p + 0.01f * (static_cast<float>(i) * s + static_cast<float>(j) * t)));
  std::nth_element(alphas.begin(), alphas.begin() + alphas.size() / 2, alphas.end());
  return alphas[alphas.size() / 2];
}

bool same_camera(const CameraDesc& a, const CameraDesc& b) {
  return same_vec(a.position, b.position) && same_vec(a.target, b.target) && same_vec(a.up, b.up) &&
         a.fov_y_deg == b.fov_y_deg && a.near_plane == b.near_plane && a.far_plane == b.far_plane;
}

bool same_light(const SpotLightDesc& a, const SpotLightDesc& b) {
  return same_vec(a.position, b.position) && same_vec(a.direction, b.direction) && same_vec(a.up, b.up) &&
         a.cone_half_angle_deg == b.cone_half_angle_deg && same_vec(a.intensity, b.intensity) &&
         a.near_plane == b.near_plane && a.far_plane == b.far_plane;
}

bool in_unit_range(glm::vec3 v) {
  return v.x >= 0.0f && v.x <= 1.0f && v.y >= 0.0f && v.y <= 1.0f && v.z >= 0.0f && v.z <= 1.0f;
}

float angle_deg(glm::vec3 a, glm::vec3 b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)) * 180.0f /
         std::numbers::pi_v<float>;
}

// Unit directions spread evenly over the sphere (Fibonacci sphere).
std::vector<glm::vec3> sphere_directions(uint32_t count) {
  std::vector<glm::vec3> dirs;
  const float golden = (1.0f + std::sqrt(5.0f)) / 2.0f;
  for (uint32_t i = 0; i < count; ++i) {
    const float z = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / static_cast<float>(count);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / golden;
    dirs.push_back({r * std::cos(phi), r * std::sin(phi), z});
  }
  return dirs;
}

TEST(SceneCatalogue, NamesAreTheThreeScenes) {
  EXPECT_EQ(scene_names(), (std::vector<std::string>{"atrium", "conference", "tiny"}));
  for (const std::string& name : scene_names()) EXPECT_EQ(make_scene(name).name, name);
}

TEST(SceneMesh, TrianglesAreWellFormedAndWoundTowardsTheirNormals) {
  for (const std::string& name : scene_names()) {
    SCOPED_TRACE(name);
    const Scene scene = make_scene(name);
    const SceneMesh& mesh = scene.mesh;
    ASSERT_FALSE(mesh.indices.empty());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (uint32_t index : mesh.indices) ASSERT_LT(index, mesh.vertices.size());
    for (const SceneVertex& v : mesh.vertices) {
      ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
      ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
      ASSERT_TRUE(in_unit_range(v.diffuse));
      ASSERT_TRUE(in_unit_range(v.specular));
      ASSERT_GT(v.roughness, 0.0f);
      ASSERT_LE(v.roughness, 1.0f);
    }
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
      const glm::vec3 a = mesh.vertices[mesh.indices[t]].position;
      const glm::vec3 b = mesh.vertices[mesh.indices[t + 1]].position;
      const glm::vec3 c = mesh.vertices[mesh.indices[t + 2]].position;
      const glm::vec3 area_vector = glm::cross(b - a, c - a);
      ASSERT_GT(glm::length(area_vector), 1e-6f) << "degenerate triangle " << t / 3;
      const glm::vec3 face = glm::normalize(area_vector);
      for (std::size_t k = 0; k < 3; ++k) {
        // Counter-clockwise seen from the normal side; smooth (cylinder) normals stay within
        // half a facet (11.25 degrees) of the face normal.
        ASSERT_GT(glm::dot(face, mesh.vertices[mesh.indices[t + k]].normal), 0.95f) << "triangle " << t / 3;
      }
    }
  }
}

TEST(SceneMesh, TriangleCountsFitTheirPurpose) {
  for (const char* name : {"atrium", "conference"}) {
    const std::size_t triangles = make_scene(name).mesh.indices.size() / 3;
    EXPECT_GE(triangles, 1000u) << name;
    EXPECT_LE(triangles, 20000u) << name;
  }
  EXPECT_LE(make_scene("tiny").mesh.indices.size() / 3, 32u);
}

TEST(SceneViews, CameraAndLightAreUsable) {
  for (const std::string& name : scene_names()) {
    SCOPED_TRACE(name);
    const Scene scene = make_scene(name);
    const SpotLightDesc& light = scene.light;
    EXPECT_NEAR(glm::length(light.direction), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(light.up), 1.0f, 1e-6f);
    EXPECT_GT(glm::length(glm::cross(light.up, light.direction)), 0.5f);
    EXPECT_GT(light.cone_half_angle_deg, 0.0f);
    EXPECT_LT(light.cone_half_angle_deg, 90.0f);
    EXPECT_GT(glm::min(light.intensity.x, glm::min(light.intensity.y, light.intensity.z)), 0.0f);
    EXPECT_GT(light.near_plane, 0.0f);
    EXPECT_GT(light.far_plane, light.near_plane);
    const CameraDesc& cam = scene.camera;
    const glm::vec3 forward = cam.target - cam.position;
    EXPECT_GT(glm::length(forward), 0.1f);
    EXPECT_NEAR(glm::length(cam.up), 1.0f, 1e-6f);
    EXPECT_GT(glm::length(glm::cross(cam.up, glm::normalize(forward))), 0.5f);
    EXPECT_GT(cam.fov_y_deg, 10.0f);
    EXPECT_LT(cam.fov_y_deg, 120.0f);
    EXPECT_GT(cam.near_plane, 0.0f);
    EXPECT_GT(cam.far_plane, cam.near_plane);
  }
}

TEST(SceneViews, SpotAxisHitsAFrontFaceWithinTheFarPlane) {
  for (const std::string& name : scene_names()) {
    SCOPED_TRACE(name);
    const Scene scene = make_scene(name);
    const auto hit = first_hit(scene.mesh, scene.light.position, scene.light.direction, scene.light.far_plane);
    ASSERT_TRUE(hit.has_value());
    EXPECT_LT(glm::dot(triangle_normal(scene.mesh, hit->triangle), scene.light.direction), 0.0f);
  }
  // Where each axis lands is part of each scene's purpose: the glossy floor of the atrium, the
  // glossy table of the conference room, the tiny floor straight below the light. The GGX alpha
  // there is the material's, its roughness map read at the hit point.
  const Scene atrium = make_scene("atrium");
  const auto floor_hit = first_hit(atrium.mesh, atrium.light.position, atrium.light.direction, 100.0f);
  ASSERT_TRUE(floor_hit.has_value());
  const SceneVertex& floor = atrium.mesh.vertices[atrium.mesh.indices[3 * floor_hit->triangle]];
  EXPECT_EQ(floor.normal, glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(floor.position.y, 0.0f);
  EXPECT_GE(floor.specular.x, 0.3f);
  EXPECT_LE(floor.specular.x, 0.5f);
  const float floor_alpha = alpha_around_hit(atrium, atrium.light.position, atrium.light.direction, *floor_hit);
  EXPECT_GE(floor_alpha, 0.05f);
  EXPECT_LE(floor_alpha, 0.2f);

  const Scene conference = make_scene("conference");
  const auto table_hit = first_hit(conference.mesh, conference.light.position, conference.light.direction, 100.0f);
  ASSERT_TRUE(table_hit.has_value());
  const SceneVertex& table = conference.mesh.vertices[conference.mesh.indices[3 * table_hit->triangle]];
  EXPECT_GE(table.specular.x, 0.5f);
  EXPECT_LE(alpha_around_hit(conference, conference.light.position, conference.light.direction, *table_hit), 0.12f);
  EXPECT_GT(table.position.y, 0.5f);  // the table top, not the floor

  const Scene tiny = make_scene("tiny");
  const auto tiny_hit = first_hit(tiny.mesh, tiny.light.position, tiny.light.direction, 100.0f);
  ASSERT_TRUE(tiny_hit.has_value());
  EXPECT_NEAR(tiny_hit->distance, 3.0f, 1e-5f);
}

TEST(SceneViews, RoomsAreClosedAndSeenFromInside) {
  // Every ray from the camera and from the light hits a front face: interior surfaces face
  // inward, no back face is ever the nearest surface, and the atrium and the conference room are
  // closed (every ray hits something). The tiny scene is open: only rays that hit are checked.
  const std::vector<glm::vec3> directions = sphere_directions(400);
  for (const std::string& name : scene_names()) {
    SCOPED_TRACE(name);
    const Scene scene = make_scene(name);
    const bool closed = name != "tiny";
    for (const glm::vec3 origin : {scene.camera.position, scene.light.position}) {
      uint32_t hits = 0;
      for (const glm::vec3& d : directions) {
        const auto hit = first_hit(scene.mesh, origin, d, 1000.0f);
        if (!hit) {
          EXPECT_FALSE(closed) << "ray escapes along (" << d.x << ", " << d.y << ", " << d.z << ")";
          continue;
        }
        ++hits;
        EXPECT_LT(glm::dot(triangle_normal(scene.mesh, hit->triangle), d), 0.0f)
            << "back face seen along (" << d.x << ", " << d.y << ", " << d.z << ")";
      }
      EXPECT_GT(hits, 0u);
    }
  }
}

TEST(SceneContent, TinySceneIsExactlyAsSpecified) {
  const Scene tiny = make_scene("tiny");
  EXPECT_TRUE(same_vec(tiny.light.position, {0.0f, 3.0f, 0.0f}));
  EXPECT_TRUE(same_vec(tiny.light.direction, {0.0f, -1.0f, 0.0f}));
  EXPECT_EQ(tiny.light.cone_half_angle_deg, 40.0f);
  EXPECT_TRUE(same_vec(tiny.light.intensity, glm::vec3(10.0f)));
  EXPECT_TRUE(same_vec(tiny.camera.position, {0.0f, 2.5f, 4.0f}));
  EXPECT_TRUE(same_vec(tiny.camera.target, {0.0f, 0.3f, 0.0f}));
  EXPECT_EQ(tiny.camera.fov_y_deg, 60.0f);

  // The floor: vertices on y = 0 facing +y, spanning exactly [-2, 2]^2, with the material the
  // RSM flux test assumes.
  glm::vec2 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  uint32_t floor_vertices = 0;
  for (const SceneVertex& v : tiny.mesh.vertices) {
    if (v.position.y != 0.0f || !same_vec(v.normal, {0.0f, 1.0f, 0.0f})) continue;
    ++floor_vertices;
    lo = glm::min(lo, glm::vec2(v.position.x, v.position.z));
    hi = glm::max(hi, glm::vec2(v.position.x, v.position.z));
    EXPECT_TRUE(same_vec(v.diffuse, glm::vec3(0.5f)));
    EXPECT_TRUE(same_vec(v.specular, glm::vec3(0.04f)));
    EXPECT_EQ(v.roughness, 0.5f);
  }
  EXPECT_GE(floor_vertices, 3u);
  EXPECT_EQ(lo, glm::vec2(-2.0f));
  EXPECT_EQ(hi, glm::vec2(2.0f));

  // A 1 m box of another colour stands on the floor.
  glm::vec3 box_lo(std::numeric_limits<float>::infinity()), box_hi(-std::numeric_limits<float>::infinity());
  for (const SceneVertex& v : tiny.mesh.vertices) {
    const bool back_wall = v.position.z == -2.0f && v.normal.z == 1.0f;
    if (v.diffuse == glm::vec3(0.5f) || back_wall) continue;  // neither floor nor back wall
    box_lo = glm::min(box_lo, v.position);
    box_hi = glm::max(box_hi, v.position);
  }
  EXPECT_EQ(box_lo.y, 0.0f);
  EXPECT_NEAR(box_hi.x - box_lo.x, 1.0f, 1e-6f);
  EXPECT_NEAR(box_hi.y - box_lo.y, 1.0f, 1e-6f);
  EXPECT_NEAR(box_hi.z - box_lo.z, 1.0f, 1e-6f);
}

TEST(SceneContent, AtriumWallsAreColoured) {
  const Scene atrium = make_scene("atrium");
  uint32_t left = 0, right = 0;
  for (const SceneVertex& v : atrium.mesh.vertices) {
    if (v.position.x == -5.0f && v.normal == glm::vec3(1.0f, 0.0f, 0.0f)) {
      ++left;
      EXPECT_GT(v.diffuse.r, v.diffuse.g);
    }
    if (v.position.x == 5.0f && v.normal == glm::vec3(-1.0f, 0.0f, 0.0f)) {
      ++right;
      EXPECT_GT(v.diffuse.g, v.diffuse.r);
    }
  }
  EXPECT_GT(left, 0u);
  EXPECT_GT(right, 0u);
}

TEST(SceneDeterminism, TwoCallsAreIdentical) {
  for (const std::string& name : scene_names()) {
    for (uint32_t frame : {0u, 3u}) {
      const Scene a = make_scene(name, frame, 8), b = make_scene(name, frame, 8);
      EXPECT_TRUE(same_mesh(a.mesh, b.mesh)) << name;
      EXPECT_TRUE(same_camera(a.camera, b.camera)) << name;
      EXPECT_TRUE(same_light(a.light, b.light)) << name;
      ASSERT_EQ(a.textures.size(), b.textures.size()) << name;
      for (std::size_t t = 0; t < a.textures.size(); ++t) {
        EXPECT_EQ(a.textures[t].rgba8, b.textures[t].rgba8) << name << " texture " << a.textures[t].name;
        EXPECT_EQ(a.textures[t].rgba32f, b.textures[t].rgba32f) << name << " texture " << a.textures[t].name;
      }
      ASSERT_EQ(a.materials.size(), b.materials.size()) << name;
    }
  }
}

TEST(SceneSequence, FrameZeroIsTheStaticSceneAndLaterFramesMoveSmoothly) {
  constexpr uint32_t kFrames = 16;
  for (const std::string& name : scene_names()) {
    SCOPED_TRACE(name);
    const Scene still = make_scene(name);
    const Scene first = make_scene(name, 0, kFrames);
    EXPECT_TRUE(same_mesh(still.mesh, first.mesh));
    EXPECT_TRUE(same_camera(still.camera, first.camera));
    EXPECT_TRUE(same_light(still.light, first.light));

    Scene previous = first;
    for (uint32_t frame = 1; frame < kFrames; ++frame) {
      const Scene current = make_scene(name, frame, kFrames);
      EXPECT_TRUE(same_mesh(still.mesh, current.mesh));  // only the views move
      EXPECT_FALSE(same_vec(current.light.position, still.light.position)) << "frame " << frame;
      EXPECT_NEAR(glm::length(current.light.direction), 1.0f, 1e-6f);
      EXPECT_GT(glm::length(glm::cross(current.light.up, current.light.direction)), 0.5f);
      // Small: within a metre and a few degrees of the static views; smooth: small steps.
      EXPECT_LT(glm::distance(current.light.position, still.light.position), 1.01f);
      EXPECT_LT(angle_deg(current.light.direction, still.light.direction), 5.0f);
      EXPECT_LT(glm::distance(current.camera.position, still.camera.position), 1.01f);
      EXPECT_LT(glm::distance(current.light.position, previous.light.position), 0.25f);
      EXPECT_LT(angle_deg(current.light.direction, previous.light.direction), 1.5f);
      previous = current;
    }
    const Scene middle = make_scene(name, kFrames / 2, kFrames);
    EXPECT_GT(angle_deg(middle.light.direction, still.light.direction), 1.0f);
    EXPECT_GT(glm::distance(middle.camera.position, still.camera.position), 0.1f);
    // The camera dollies: it keeps its view direction (sine of the angle between them ~ 0).
    const glm::vec3 middle_forward = glm::normalize(middle.camera.target - middle.camera.position);
    const glm::vec3 still_forward = glm::normalize(still.camera.target - still.camera.position);
    EXPECT_LT(glm::length(glm::cross(middle_forward, still_forward)), 1e-5f);
  }
}

TEST(SceneErrors, UnknownNamesAndBadFramesThrowInputError) {
  try {
    make_scene("cornell");
    FAIL() << "no exception for an unknown scene";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cornell"), std::string::npos) << message;
    for (const std::string& name : scene_names()) EXPECT_NE(message.find(name), std::string::npos) << message;
  }
  EXPECT_THROW(make_scene(""), InputError);
  EXPECT_THROW(make_scene("tiny", 0, 0), InputError);
  EXPECT_THROW(make_scene("tiny", 4, 4), InputError);
  EXPECT_THROW(make_scene("atrium", 1, 1), InputError);
  EXPECT_NO_THROW(make_scene("atrium", 3, 4));
}

TEST(SceneGeometry, DistanceToMesh) {
  const Scene tiny = make_scene("tiny");
  for (const SceneVertex& v : tiny.mesh.vertices) EXPECT_EQ(distance_to_mesh(tiny.mesh, v.position), 0.0f);
  // Above and below the floor, away from the box (x in [0.5, 1.5], z in [-1.5, -0.5]) and the
  // back wall (z = -2).
  EXPECT_NEAR(distance_to_mesh(tiny.mesh, {-1.0f, 0.7f, 1.0f}), 0.7f, 1e-6f);
  EXPECT_NEAR(distance_to_mesh(tiny.mesh, {-1.0f, -0.3f, 1.0f}), 0.3f, 1e-6f);
  // Beyond the floor's corner (2, 0, 2): distance to that corner.
  EXPECT_NEAR(distance_to_mesh(tiny.mesh, {3.0f, 0.0f, 3.0f}), std::sqrt(2.0f), 1e-6f);
  // Beside the box's +x face at x = 1.5, half way up.
  EXPECT_NEAR(distance_to_mesh(tiny.mesh, {1.75f, 0.5f, -1.0f}), 0.25f, 1e-6f);
  EXPECT_EQ(distance_to_mesh(SceneMesh{}, {0.0f, 0.0f, 0.0f}), std::numeric_limits<float>::infinity());
}

TEST(SceneGeometry, BuildersWindTowardsTheRequestedSide) {
  const SurfaceMaterial m{};
  SceneMesh mesh;
  add_axis_rect(mesh, {0.0f, 0.0f, 0.0f}, {1.0f, 2.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, m, 0.5f);
  EXPECT_EQ(mesh.indices.size() / 3, 2u * 2u * 4u);  // 2 x 4 cells of two triangles
  for (uint32_t t = 0; t < mesh.indices.size() / 3; ++t) {
    EXPECT_EQ(triangle_normal(mesh, t), glm::vec3(0.0f, 0.0f, -1.0f));
  }
  // A box seen from outside and a room seen from inside: a ray from the centre hits the room's
  // walls front-on and the box's walls from behind.
  SceneMesh box, room;
  add_box(box, glm::vec3(-1.0f), glm::vec3(1.0f), m);
  add_room(room, glm::vec3(-1.0f), glm::vec3(1.0f), {m, m, m, m, m, m}, 0.5f);
  EXPECT_EQ(box.indices.size() / 3, 12u);
  for (const glm::vec3& d : sphere_directions(64)) {
    const auto box_hit = first_hit(box, glm::vec3(0.0f), d, 10.0f);
    const auto room_hit = first_hit(room, glm::vec3(0.0f), d, 10.0f);
    ASSERT_TRUE(box_hit && room_hit);
    EXPECT_GT(glm::dot(triangle_normal(box, box_hit->triangle), d), 0.0f);
    EXPECT_LT(glm::dot(triangle_normal(room, room_hit->triangle), d), 0.0f);
  }
  // Leaving out faces: a box without its bottom has no triangle facing -y.
  SceneMesh open_box;
  add_box(open_box, glm::vec3(0.0f), glm::vec3(1.0f), m, kBoxAllFaces & ~kBoxNegY);
  EXPECT_EQ(open_box.indices.size() / 3, 10u);
  for (const SceneVertex& v : open_box.vertices) EXPECT_NE(v.normal, glm::vec3(0.0f, -1.0f, 0.0f));
}

TEST(SceneGeometry, FirstHitFindsTheNearestSurface) {
  const Scene tiny = make_scene("tiny");
  // Straight down onto the box top (y = 1) rather than the floor behind it.
  const auto box_top = first_hit(tiny.mesh, {1.0f, 3.0f, -1.0f}, {0.0f, -1.0f, 0.0f}, 10.0f);
  ASSERT_TRUE(box_top.has_value());
  EXPECT_NEAR(box_top->distance, 2.0f, 1e-6f);
  const auto floor = first_hit(tiny.mesh, {-1.0f, 3.0f, 1.0f}, {0.0f, -1.0f, 0.0f}, 10.0f);
  ASSERT_TRUE(floor.has_value());
  EXPECT_NEAR(floor->distance, 3.0f, 1e-6f);
  // Limited by max_distance, and nothing up there.
  EXPECT_FALSE(first_hit(tiny.mesh, {-1.0f, 3.0f, 1.0f}, {0.0f, -1.0f, 0.0f}, 2.5f).has_value());
  EXPECT_FALSE(first_hit(tiny.mesh, {-1.0f, 3.0f, 1.0f}, {0.0f, 1.0f, 0.0f}, 100.0f).has_value());
}

}  // namespace
}  // namespace vsgl
