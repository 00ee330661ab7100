// The procedural surface detail of the built-in scenes (surface_detail.hpp): each pattern is what
// it says (grout darker, rougher and recessed; rings in the wood; smudges on the gloss), its maps
// encode it faithfully, and the scenes carry it on the surfaces the light and the camera see.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "harness/scene/scene.hpp"
#include "harness/scene/scene_textures.hpp"
#include "harness/scene/surface_detail.hpp"

namespace vsgl {
namespace {

std::size_t at(const DetailPlanes& p, uint32_t x, uint32_t y) { return std::size_t{y} * p.size + x; }

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

std::pair<float, float> alpha_range(const DetailPlanes& p) {
  const auto [lo, hi] = std::minmax_element(p.alpha.begin(), p.alpha.end());
  return {*lo, *hi};
}

TEST(SurfaceDetail, EveryPatternIsInRangeAndNotFlat) {
  for (const DetailPlanes& p : {stone_floor_tiles(), ashlar_wall(), speckled_stone(), carpet_tiles(), painted_brick(),
                                wall_panels(), wood_grain(0.07f), smudged_gloss()}) {
    SCOPED_TRACE(p.name);
    ASSERT_EQ(p.size, kDetailTexelsPerMetre);
    ASSERT_EQ(p.albedo.size(), std::size_t{p.size} * p.size);
    float lo = 1.0f, hi = 0.0f;
    for (std::size_t i = 0; i < p.albedo.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_GE(p.albedo[i][c], 0.0f);
        ASSERT_LE(p.albedo[i][c], 1.0f);
      }
      ASSERT_GT(p.alpha[i], 0.0f);
      ASSERT_LE(p.alpha[i], 1.0f);
      if (!p.height.empty()) {
        ASSERT_TRUE(std::isfinite(p.height[i]));
      }
      lo = std::min(lo, luminance(p.albedo[i]));
      hi = std::max(hi, luminance(p.albedo[i]));
    }
    const auto [alpha_lo, alpha_hi] = alpha_range(p);
    EXPECT_TRUE(hi - lo > 0.05f || alpha_hi > 1.5f * alpha_lo) << "a pattern without detail";
  }
}

TEST(SurfaceDetail, FloorGroutIsDarkerRougherAndRecessed) {
  const DetailPlanes p = stone_floor_tiles();
  // 50 cm tiles from the corner: joints at u, v = 0 and 0.5 m (texel 0 and 128); centres at 64.
  const std::size_t grout = at(p, 128, 64), tile = at(p, 64, 64);
  EXPECT_LT(luminance(p.albedo[grout]), 0.6f * luminance(p.albedo[tile]));
  EXPECT_GT(p.alpha[grout], 3.0f * p.alpha[tile]);
  EXPECT_LT(p.height[grout], p.height[tile] - 0.001f);
}

TEST(SurfaceDetail, BricksAreLaidInRunningBond) {
  const DetailPlanes p = painted_brick();
  // 25 x 6.25 cm bricks: course 0 has head joints at u = 0, 0.25 m...; course 1 (v in 6.25-12.5
  // cm) is shifted by half a brick, so its joints are at 0.125 m + k 0.25 m.
  const uint32_t course0 = 8, course1 = 24;  // texel rows in the middle of each course
  EXPECT_LT(p.height[at(p, 64, course0)], p.height[at(p, 32, course0)] - 0.002f);
  EXPECT_LT(p.height[at(p, 32, course1)], p.height[at(p, 64, course1)] - 0.002f);
}

TEST(SurfaceDetail, WoodHasRingsAcrossTheGrainAndAFinishOfItsOwn) {
  const DetailPlanes polished = wood_grain(0.07f), satin = wood_grain(0.4f);
  EXPECT_NE(polished.name, satin.name);
  // Across the grain (down a column) the rings alternate light and dark every ~12 mm (3 texels).
  uint32_t crossings = 0;
  float mean = 0.0f;
  for (uint32_t y = 0; y < 32; ++y) mean += luminance(polished.albedo[at(polished, 10, y)]) / 32.0f;
  for (uint32_t y = 1; y < 32; ++y) {
    const bool above = luminance(polished.albedo[at(polished, 10, y)]) > mean;
    const bool before = luminance(polished.albedo[at(polished, 10, y - 1)]) > mean;
    crossings += above != before ? 1u : 0u;
  }
  EXPECT_GE(crossings, 6u) << "growth rings across 12.5 cm of plank";
  const auto [p_lo, p_hi] = alpha_range(polished);
  const auto [s_lo, s_hi] = alpha_range(satin);
  EXPECT_LT(p_hi, s_lo) << "the lacquered top is glossier everywhere than the satin wood";
  EXPECT_GT(p_hi, 1.3f * p_lo) << "roughness varies on the glossy surface";
}

TEST(SurfaceDetail, HeightNormalTiltsAwayFromTheSlope) {
  constexpr uint32_t n = 8;
  std::vector<float> ramp(n * n);
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) ramp[y * n + x] = 0.01f * static_cast<float>(std::min(x, n - x));
  const glm::vec3 rising = height_normal(ramp, n, 2, 3);  // height grows with u here
  EXPECT_LT(rising.x, -0.01f);
  EXPECT_NEAR(rising.y, 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(rising), 1.0f, 1e-6f);
  // slope 0.01 m per 1/8 m texel: normal (-0.08, 0, 1) normalised
  EXPECT_NEAR(rising.x, -0.08f / std::sqrt(1.0f + 0.0064f), 1e-5f);
  EXPECT_GT(height_normal(ramp, n, 6, 3).x, 0.01f) << "falling towards the wrap";
}

TEST(SurfaceDetail, MaterialMapsEncodeThePlanes) {
  Scene scene;
  const DetailPlanes p = stone_floor_tiles();
  const DetailMaterial m = add_surface_detail(scene, p);
  ASSERT_EQ(m.material, 0u);
  ASSERT_EQ(scene.materials.size(), 1u);
  ASSERT_EQ(scene.textures.size(), 3u);
  const Material& mat = scene.materials[0];
  EXPECT_EQ(mat.model, MaterialModel::kVertexAlbedo);
  ASSERT_GE(mat.base_color_texture, 0);
  ASSERT_GE(mat.metallic_roughness_texture, 0);
  ASSERT_GE(mat.normal_texture, 0);
  const TextureImage& albedo = scene.textures[static_cast<std::size_t>(mat.base_color_texture)];
  const TextureImage& rough = scene.textures[static_cast<std::size_t>(mat.metallic_roughness_texture)];
  const TextureImage& normal = scene.textures[static_cast<std::size_t>(mat.normal_texture)];
  EXPECT_TRUE(albedo.srgb);
  EXPECT_FALSE(rough.srgb);
  EXPECT_FALSE(normal.srgb);
  EXPECT_EQ(m.max_alpha, alpha_range(p).second);
  const SurfaceMaterial surface = detailed_surface(m, glm::vec3(0.4f), glm::vec3(0.4f));
  EXPECT_EQ(surface.material, m.material);
  EXPECT_EQ(surface.roughness, m.max_alpha);
  for (uint32_t i : {0u, 64u * 256u + 64u, 64u * 256u + 128u, 200u * 256u + 33u}) {
    // alpha = vertex roughness (max alpha) * G^2, to 8-bit precision.
    const float g = rough.rgba8[4 * i + 1] / 255.0f;
    EXPECT_NEAR(surface.roughness * g * g, p.alpha[i], 0.01f * surface.roughness) << "texel " << i;
    EXPECT_NEAR(srgb_to_linear(albedo.rgba8[4 * i] / 255.0f), p.albedo[i].r, 0.01f) << "texel " << i;
    const glm::vec3 decoded = glm::vec3(normal.rgba8[4 * i], normal.rgba8[4 * i + 1], normal.rgba8[4 * i + 2]) /
                                  255.0f * 2.0f - 1.0f;
    EXPECT_GT(glm::dot(glm::normalize(decoded), height_normal(p.height, p.size, i % 256, i / 256)), 0.999f);
  }
  // Build the mip chain as the recorder does: the maps are well-formed textures.
  EXPECT_EQ(build_mip_chain(albedo).size(), 9u);
}

TEST(SurfaceDetail, ScenesCarryDetailWhereTheLightFalls) {
  for (const char* name : {"atrium", "conference"}) {
    SCOPED_TRACE(name);
    const Scene scene = make_scene(name);
    EXPECT_GE(scene.materials.size(), 3u);
    std::size_t normal_maps = 0;
    for (const Material& m : scene.materials) normal_maps += m.normal_texture >= 0 ? 1u : 0u;
    EXPECT_GE(normal_maps, 2u);
    // Most of the mesh's triangles carry a material, the floor's among them.
    std::size_t textured = 0;
    for (std::size_t t = 0; t < scene.mesh.indices.size(); t += 3) {
      const SceneVertex& v = scene.mesh.vertices[scene.mesh.indices[t]];
      textured += v.material != kNoMaterial ? 1u : 0u;
      if (v.material != kNoMaterial) {
        ASSERT_LT(v.material, scene.materials.size());
      }
    }
    EXPECT_GT(2 * textured, scene.mesh.indices.size() / 3);
  }
  EXPECT_TRUE(make_scene("tiny").materials.empty()) << "the test scene stays plain";
}

}  // namespace
}  // namespace vsgl
