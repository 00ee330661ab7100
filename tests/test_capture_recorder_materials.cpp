// The material path of the recorder: textures sampled from their mip chains, the DESIGN.md §3
// metallic-roughness mapping, normal maps in the tangent frame, alpha-mask cut-outs and
// double-sided surfaces, in the G-buffer and the RSM; and the CPU parts (mip chains, tangents).
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_test.hpp"
#include "harness/core/error.hpp"
#include "harness/capture/view_matrices.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/scene/scene.hpp"
#include "harness/scene/scene_geometry.hpp"
#include "harness/scene/scene_textures.hpp"

namespace vsgl {
namespace {

// sRGB bytes of the two checker colours.
constexpr uint8_t kLight[3] = {200, 100, 50};
constexpr uint8_t kDark[3] = {20, 40, 60};

// A 64x64 checker of 32-texel squares; the alpha is 0 on the left half (u < 0.5) when asked.
TextureImage checker(bool alpha_left_zero) {
  TextureImage t;
  t.name = "checker";
  t.width = t.height = 64;
  t.srgb = true;
  t.rgba8.resize(64 * 64 * 4);
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      const bool light = ((x / 32) + (y / 32)) % 2 == 0;
      uint8_t* p = &t.rgba8[(y * 64 + x) * 4];
      for (int c = 0; c < 3; ++c) p[c] = light ? kLight[c] : kDark[c];
      p[3] = alpha_left_zero && x < 32 ? 0 : 255;
    }
  return t;
}

glm::vec3 linear(const uint8_t (&c)[3]) {
  return {srgb_to_linear(c[0] / 255.0f), srgb_to_linear(c[1] / 255.0f), srgb_to_linear(c[2] / 255.0f)};
}

// A 2 x 2 m floor at y = 0 (texture coordinates = metres from its -x,-z corner along z and x, so
// one checker square is 0.5 m), seen and lit straight from above.
Scene floor_scene(const Material& material, std::vector<TextureImage> textures, bool facing_down = false) {
  Scene scene;
  scene.name = "material_floor";
  // With a metallic-roughness material the vertex's diffuse field is its vertex colour (white here);
  // with the vertex-albedo model it is the albedo the maps modulate.
  const bool mr = material.model == MaterialModel::kMetallicRoughness;
  SurfaceMaterial surface{glm::vec3(mr ? 1.0f : 0.5f), glm::vec3(0.04f), 0.5f, 0};
  if (facing_down) {
    add_axis_rect(scene.mesh, {-1.0f, 0.0f, -1.0f}, {1.0f, 0.0f, 1.0f}, {0.0f, -1.0f, 0.0f}, surface, 2.0f);
  } else {
    add_axis_rect(scene.mesh, {-1.0f, 0.0f, -1.0f}, {1.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f}, surface, 2.0f);
  }
  scene.materials = {material};
  scene.textures = std::move(textures);
  scene.camera.position = {0.0f, 2.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  scene.camera.fov_y_deg = 50.0f;
  scene.camera.near_plane = 0.1f;
  scene.camera.far_plane = 10.0f;
  scene.light.position = {0.0f, 2.0f, 0.0f};
  scene.light.direction = {0.0f, -1.0f, 0.0f};
  scene.light.up = spot_light_up(scene.light.direction);
  scene.light.cone_half_angle_deg = 40.0f;
  scene.light.intensity = glm::vec3(10.0f);
  scene.light.near_plane = 0.1f;
  scene.light.far_plane = 10.0f;
  return scene;
}

// The checker square a floor point lies in, and its distance to the nearest square edge.
// Along the quad: u runs along +x from x = -1 and v along +z from z = -1 (add_axis_rect's rule);
// texel (x_t, y_t) of the image is at (u, v) * 32 in its 64-texel period of 2 m.
bool light_square(glm::vec3 p) {
  const float u = p.x + 1.0f, v = p.z + 1.0f;
  const int iu = static_cast<int>(std::floor(u / 0.5f)), iv = static_cast<int>(std::floor(v / 0.5f));
  return (iu + iv) % 2 == 0;
}
float edge_distance(glm::vec3 p) {
  const float u = p.x + 1.0f, v = p.z + 1.0f;
  const auto d = [](float s) { return std::abs(s / 0.5f - std::round(s / 0.5f)) * 0.5f; };
  return std::min(d(u), d(v));
}

class SceneMaterialsTest : public test::GpuTest {
 protected:
  static constexpr RecordSizes kSizes{64, 64, 64};
  Capture record(const Scene& scene) { return CaptureRecorder(device()).record(scene, kSizes, 0, 1); }
};

TEST_F(SceneMaterialsTest, MetallicRoughnessTexturesFollowSpecSection3) {
  Material m;
  m.model = MaterialModel::kMetallicRoughness;
  m.metallic_factor = 0.25f;
  m.roughness_factor = 0.6f;
  m.base_color_texture = 0;
  const Scene scene = floor_scene(m, {checker(false)});
  const Capture cap = record(scene);
  const ViewImage& g = cap.gbuffer;
  std::size_t light = 0, dark = 0;
  for (uint32_t y = 0; y < g.height; ++y)
    for (uint32_t x = 0; x < g.width; ++x) {
      if (g.at(kValid, x, y) == 0.0f) continue;
      const glm::vec3 p(g.at(kPX, x, y), g.at(kPY, x, y), g.at(kPZ, x, y));
      EXPECT_NEAR(p.y, 0.0f, 1e-5f);
      EXPECT_NEAR(g.at(kRoughness, x, y), 0.36f, 1e-6f) << "GGX alpha = roughness^2";
      if (edge_distance(p) < 0.1f) continue;  // filtering blends the squares near their edges
      const glm::vec3 base = light_square(p) ? linear(kLight) : linear(kDark);
      (light_square(p) ? light : dark)++;
      const glm::vec3 diffuse(g.at(kDR, x, y), g.at(kDG, x, y), g.at(kDB, x, y));
      const glm::vec3 specular(g.at(kSR, x, y), g.at(kSG, x, y), g.at(kSB, x, y));
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(diffuse[c], base[c] * 0.75f, 3e-3f) << "diffuse = base (1 - metallic) at " << x << "," << y;
        EXPECT_NEAR(specular[c], 0.04f * 0.75f + base[c] * 0.25f, 3e-3f) << "F0 = mix(0.04, base, metallic)";
      }
    }
  EXPECT_GT(light, 100u);
  EXPECT_GT(dark, 100u);

  // The RSM carries the same albedos times the incident flux.
  const ViewImage& r = cap.rsm;
  const float area = rsm_texel_area(scene.light, kSizes.rsm_size);
  std::size_t checked = 0;
  for (uint32_t y = 0; y < r.height; ++y)
    for (uint32_t x = 0; x < r.width; ++x) {
      if (r.at(kValid, x, y) == 0.0f) continue;
      const glm::vec3 p(r.at(kPX, x, y), r.at(kPY, x, y), r.at(kPZ, x, y));
      const float cos_theta = glm::dot(glm::normalize(p - scene.light.position), scene.light.direction);
      if (cos_theta < std::cos(glm::radians(scene.light.cone_half_angle_deg)) + 1e-3f || edge_distance(p) < 0.1f) continue;
      const float incident = 10.0f * area * cos_theta * cos_theta * cos_theta;
      const glm::vec3 base = light_square(p) ? linear(kLight) : linear(kDark);
      EXPECT_NEAR(r.at(kDR, x, y) / incident, base.r * 0.75f, 3e-3f) << "RSM texel " << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 100u);
}

TEST_F(SceneMaterialsTest, MetallicRoughnessMapScalesTheFactors) {
  Material m;
  m.model = MaterialModel::kMetallicRoughness;
  m.base_color_factor = glm::vec4(0.5f, 0.25f, 1.0f, 1.0f);
  m.metallic_factor = 1.0f;
  m.roughness_factor = 1.0f;
  m.metallic_roughness_texture = 0;
  TextureImage mr;
  mr.name = "mr";
  mr.width = mr.height = 4;
  for (int i = 0; i < 16; ++i) mr.rgba8.insert(mr.rgba8.end(), {0, 128, 255, 255});  // roughness 0.502, metal 1
  const Capture cap = record(floor_scene(m, {mr}));
  const ViewImage& g = cap.gbuffer;
  std::size_t valid = 0;
  const float rough = 128.0f / 255.0f;
  for (std::size_t i = 0; i < g.texels(); ++i) {
    if (g.planes[kValid][i] == 0.0f) continue;
    ++valid;
    EXPECT_NEAR(g.planes[kRoughness][i], rough * rough, 1e-4f);
    EXPECT_EQ(g.planes[kDR][i], 0.0f) << "a metal has no diffuse albedo";
    EXPECT_NEAR(g.planes[kSR][i], 0.5f, 1e-5f);
    EXPECT_NEAR(g.planes[kSG][i], 0.25f, 1e-5f);
    EXPECT_NEAR(g.planes[kSB][i], 1.0f, 1e-5f);
  }
  EXPECT_GT(valid, g.texels() / 2);
}

TEST_F(SceneMaterialsTest, NormalMapTiltsTheNormalInTheTangentFrame) {
  Material m;
  m.model = MaterialModel::kVertexAlbedo;
  m.normal_texture = 0;
  TextureImage n;
  n.name = "tilt";
  n.width = n.height = 4;
  for (int i = 0; i < 16; ++i) n.rgba8.insert(n.rgba8.end(), {204, 128, 230, 255});
  const Capture cap = record(floor_scene(m, {n}));
  // The floor's tangent is +x (u runs along x), the bitangent +z (v runs along z).
  const glm::vec3 ts(204.0f / 255.0f * 2.0f - 1.0f, 128.0f / 255.0f * 2.0f - 1.0f, 230.0f / 255.0f * 2.0f - 1.0f);
  const glm::vec3 expected = glm::normalize(glm::vec3(1.0f, 0.0f, 0.0f) * ts.x + glm::vec3(0.0f, 0.0f, 1.0f) * ts.y +
                                            glm::vec3(0.0f, 1.0f, 0.0f) * ts.z);
  const ViewImage& g = cap.gbuffer;
  std::size_t valid = 0;
  for (std::size_t i = 0; i < g.texels(); ++i) {
    if (g.planes[kValid][i] == 0.0f) continue;
    ++valid;
    const glm::vec3 normal(g.planes[kNX][i], g.planes[kNY][i], g.planes[kNZ][i]);
    EXPECT_NEAR(glm::length(normal), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(normal, expected), 1.0f, 1e-4f) << "texel " << i;
    EXPECT_NEAR(g.planes[kDR][i], 0.5f, 1e-6f) << "vertex albedo with a white (absent) base map";
    EXPECT_NEAR(g.planes[kRoughness][i], 0.5f, 1e-6f);
  }
  EXPECT_GT(valid, g.texels() / 2);
}

TEST_F(SceneMaterialsTest, AlphaMaskCutsOutAndDoubleSidedShowsTheBack) {
  Material m;
  m.model = MaterialModel::kMetallicRoughness;
  m.metallic_factor = 0.0f;
  m.alpha_mask = true;
  m.alpha_cutoff = 0.5f;
  m.base_color_texture = 0;
  const Capture cap = record(floor_scene(m, {checker(true)}));
  std::size_t kept = 0, cut = 0;
  const ViewImage& g = cap.gbuffer;
  const ViewMatrices cam = camera_matrices(floor_scene(m, {}).camera, 1.0f);
  for (uint32_t y = 0; y < g.height; ++y)
    for (uint32_t x = 0; x < g.width; ++x) {
      // Where the pixel's ray meets the floor plane y = 0.
      const glm::vec2 ndc((static_cast<float>(x) + 0.5f) / static_cast<float>(g.width) * 2.0f - 1.0f,
                          (static_cast<float>(y) + 0.5f) / static_cast<float>(g.height) * 2.0f - 1.0f);
      const glm::mat4 inv = glm::inverse(cam.projection * cam.view);
      glm::vec4 a = inv * glm::vec4(ndc, 0.0f, 1.0f), b = inv * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
      const glm::vec3 hit = p0 + (p1 - p0) * (p0.y / (p0.y - p1.y));
      if (std::abs(hit.x) > 0.95f || std::abs(hit.z) > 0.95f) continue;
      // The alpha is zero on texels x < 32: where the fraction of u (metres along +x) is below 0.5.
      const float u = hit.x + 1.0f, fu = u - std::floor(u);
      if (std::abs(fu - 0.5f) < 0.1f || fu < 0.1f || fu > 0.9f) continue;
      if (fu < 0.5f) {
        EXPECT_EQ(g.at(kValid, x, y), 0.0f) << "cut-out texel drawn at " << x << "," << y;
        ++cut;
      } else {
        EXPECT_EQ(g.at(kValid, x, y), 1.0f) << "opaque texel missing at " << x << "," << y;
        ++kept;
      }
    }
  EXPECT_GT(cut, 200u);
  EXPECT_GT(kept, 200u);

  // A floor facing down is culled, unless its material is double-sided: then it is seen with its
  // normal turned towards the camera.
  Material one_sided;
  EXPECT_EQ(record(floor_scene(one_sided, {}, true)).gbuffer.planes[kValid],
            std::vector<float>(g.texels(), 0.0f));
  Material two_sided;
  two_sided.double_sided = true;
  const Capture back = record(floor_scene(two_sided, {}, true));
  std::size_t seen = 0;
  for (std::size_t i = 0; i < back.gbuffer.texels(); ++i) {
    if (back.gbuffer.planes[kValid][i] == 0.0f) continue;
    ++seen;
    EXPECT_NEAR(back.gbuffer.planes[kNY][i], 1.0f, 1e-6f);
  }
  EXPECT_GT(seen, g.texels() / 2);
}

TEST(SceneTextures, MipChainAveragesSrgbInLinearSpace) {
  TextureImage t;
  t.name = "t";
  t.width = 5;
  t.height = 3;
  t.srgb = true;
  for (uint32_t i = 0; i < 15; ++i) t.rgba8.insert(t.rgba8.end(), {static_cast<uint8_t>(i % 2 ? 255 : 0), 0, 0, 255});
  const auto levels = build_mip_chain(t);
  ASSERT_EQ(levels.size(), 3u);  // 5x3, 2x1, 1x1
  EXPECT_EQ(levels[1].width, 2u);
  EXPECT_EQ(levels[1].height, 1u);
  EXPECT_EQ(levels[2].width, 1u);
  // Texel (0,0) of level 1 averages columns 0 and 1 (black, white): linear 0.5 = sRGB 188.
  EXPECT_EQ(levels[1].rgba8[0], 188);
  EXPECT_EQ(levels[1].rgba8[3], 255);

  TextureImage f;
  f.name = "f";
  f.width = f.height = 2;
  f.rgba32f = {1, 0, 0, 0, 3, 0, 0, 0, 5, 0, 0, 0, 7, 0, 0, 0};
  const auto fl = build_mip_chain(f);
  ASSERT_EQ(fl.size(), 2u);
  EXPECT_EQ(fl[1].rgba32f[0], 4.0f);

  TextureImage bad = f;
  bad.rgba32f.pop_back();
  EXPECT_THROW(build_mip_chain(bad), InputError);
}

TEST(SceneTextures, TangentsFollowTheTextureCoordinates) {
  // A quad in the xz plane facing +y with u along +x and v along -z: the tangent is +x and
  // cross(n, t) = +y x +x = -z is +v, so the handedness is +1; mirroring u flips it.
  const auto quad = [](float u_sign) {
    std::vector<SceneVertex> v(4);
    const glm::vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {1, 0, -1}, {0, 0, -1}};
    const glm::vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i) {
      v[i].position = p[i];
      v[i].normal = {0, 1, 0};
      v[i].uv = {uv[i].x * u_sign, uv[i].y};
    }
    return v;
  };
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};
  auto v = quad(1.0f);
  compute_tangents(v, idx);
  for (const SceneVertex& s : v) {
    EXPECT_NEAR(s.tangent.x, 1.0f, 1e-6f);
    EXPECT_NEAR(s.tangent.w, 1.0f, 0.0f);
  }
  auto m = quad(-1.0f);
  compute_tangents(m, idx);
  for (const SceneVertex& s : m) {
    EXPECT_NEAR(s.tangent.x, -1.0f, 1e-6f);
    EXPECT_NEAR(s.tangent.w, -1.0f, 0.0f) << "mirrored texture coordinates flip the handedness";
  }
}

}  // namespace
}  // namespace vsgl
