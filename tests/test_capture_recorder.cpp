// The recorder against the scene it rasterized (DESIGN.md §3): positions on the scene's surfaces,
// unit normals facing the viewer, camera PDF = reflectance luminance, RSM flux zero outside the
// cone and following I * texel_area * cos^3(theta) * albedo inside it, and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gpu_test.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/scene/scene.hpp"
#include "harness/scene/scene_geometry.hpp"
#include "harness/capture/view_matrices.hpp"

namespace vsgl {
namespace {

class CaptureRecorderTest : public test::GpuTest {
 protected:
  static constexpr RecordSizes kSizes{96, 64, 64};
  Capture record_tiny() {
    CaptureRecorder recorder(device());
    return recorder.record(make_scene("tiny"), kSizes, 0, 1);
  }
};

TEST_F(CaptureRecorderTest, GBufferLiesOnTheSceneAndFacesTheCamera) {
  const Scene scene = make_scene("tiny");
  const Capture cap = record_tiny();
  const ViewImage& g = cap.gbuffer;
  ASSERT_EQ(g.width, kSizes.gbuffer_width);
  ASSERT_EQ(g.height, kSizes.gbuffer_height);
  std::size_t valid = 0;
  for (uint32_t y = 0; y < g.height; ++y)
    for (uint32_t x = 0; x < g.width; ++x) {
      const float v = g.at(kValid, x, y);
      ASSERT_TRUE(v == 0.0f || v == 1.0f);
      if (v == 0.0f) continue;
      ++valid;
      const glm::vec3 p(g.at(kPX, x, y), g.at(kPY, x, y), g.at(kPZ, x, y));
      const glm::vec3 n(g.at(kNX, x, y), g.at(kNY, x, y), g.at(kNZ, x, y));
      EXPECT_LT(distance_to_mesh(scene.mesh, p), 1e-3f) << "texel " << x << "," << y;
      EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
      EXPECT_GT(glm::dot(n, scene.camera.position - p), 0.0f) << "back face visible at " << x << "," << y;
      const glm::vec3 rho(g.at(kDR, x, y) + g.at(kSR, x, y), g.at(kDG, x, y) + g.at(kSG, x, y),
                          g.at(kDB, x, y) + g.at(kSB, x, y));
      EXPECT_NEAR(g.at(kPdf, x, y), 0.2126f * rho.r + 0.7152f * rho.g + 0.0722f * rho.b, 1e-6f);
      EXPECT_GT(g.at(kRoughness, x, y), 0.0f);
    }
  EXPECT_GT(valid, g.texels() / 4) << "the tiny scene should fill a good part of the camera view";
  EXPECT_TRUE(g.has_pdf);
  EXPECT_FALSE(cap.rsm.has_pdf) << "the BRSM PDF is not built by the recorder";
}

TEST_F(CaptureRecorderTest, RsmFluxFollowsTheSpotCosineCubedLaw) {
  const Scene scene = make_scene("tiny");
  const Capture cap = record_tiny();
  const ViewImage& r = cap.rsm;
  const SpotLightDesc& light = scene.light;
  const float area = rsm_texel_area(light, kSizes.rsm_size);
  const float cos_cone = std::cos(glm::radians(light.cone_half_angle_deg));
  std::size_t inside = 0, outside = 0;
  for (uint32_t y = 0; y < r.height; ++y)
    for (uint32_t x = 0; x < r.width; ++x) {
      if (r.at(kValid, x, y) == 0.0f) continue;
      const glm::vec3 p(r.at(kPX, x, y), r.at(kPY, x, y), r.at(kPZ, x, y));
      const float cos_theta = glm::dot(glm::normalize(p - light.position), glm::normalize(light.direction));
      const glm::vec3 flux_d(r.at(kDR, x, y), r.at(kDG, x, y), r.at(kDB, x, y));
      const glm::vec3 flux_s(r.at(kSR, x, y), r.at(kSG, x, y), r.at(kSB, x, y));
      if (cos_theta < cos_cone - 1e-4f) {
        ++outside;
        EXPECT_EQ(flux_d, glm::vec3(0.0f)) << "flux outside the cone at " << x << "," << y;
        EXPECT_EQ(flux_s, glm::vec3(0.0f));
        continue;
      }
      if (cos_theta < cos_cone + 1e-4f) continue;  // on the cone's edge either answer is right
      // The tiny scene's floor (y = 0) has diffuse albedo 0.5 and specular 0.04.
      if (std::abs(p.y) > 1e-4f) continue;
      ++inside;
      const float expected = light.intensity.r * area * cos_theta * cos_theta * cos_theta;
      EXPECT_NEAR(flux_d.r, expected * 0.5f, expected * 0.5f * 1e-4f) << "texel " << x << "," << y;
      EXPECT_NEAR(flux_s.g, expected * 0.04f, expected * 0.04f * 1e-4f);
    }
  EXPECT_GT(inside, 100u) << "the spot should light a good part of the floor";
  EXPECT_GT(outside, 0u) << "the RSM corners lie outside the inscribed cone";
}

TEST_F(CaptureRecorderTest, RecordingIsDeterministic) {
  const Capture a = record_tiny();
  const Capture b = record_tiny();
  for (int c = 0; c < kChannelCount; ++c) {
    EXPECT_EQ(plane_hash(a.gbuffer.planes[c]), plane_hash(b.gbuffer.planes[c])) << "gbuffer channel " << c;
    EXPECT_EQ(plane_hash(a.rsm.planes[c]), plane_hash(b.rsm.planes[c])) << "rsm channel " << c;
  }
}

// The built-in scenes' surface detail reaches the capture, and recording them twice gives the
// same hashes. Against the same scene without its materials (the vertex constants alone): on the
// surface the light is aimed at (the atrium's floor, the conference table's top) the camera sees
// a spread of roughness, and the light view's flux varies from texel to texel far more.
TEST_F(CaptureRecorderTest, DetailedScenesRecordTheirDetailDeterministically) {
  struct Case {
    const char* scene;
    float surface_y;
  };
  for (const Case& k : {Case{"atrium", 0.0f}, Case{"conference", 0.75f}}) {
    SCOPED_TRACE(k.scene);
    CaptureRecorder recorder(device());
    const RecordSizes sizes{240, 136, 256};
    const Scene detailed = make_scene(k.scene);
    Scene plain = detailed;
    for (SceneVertex& v : plain.mesh.vertices) v.material = kNoMaterial;
    plain.materials.clear();
    plain.textures.clear();
    const Capture a = recorder.record(detailed, sizes, 0, 1);
    const Capture b = recorder.record(make_scene(k.scene), sizes, 0, 1);
    const Capture flat = recorder.record(plain, sizes, 0, 1);
    for (int c = 0; c < kChannelCount; ++c) {
      EXPECT_EQ(plane_hash(a.gbuffer.planes[c]), plane_hash(b.gbuffer.planes[c])) << "gbuffer channel " << c;
      EXPECT_EQ(plane_hash(a.rsm.planes[c]), plane_hash(b.rsm.planes[c])) << "rsm channel " << c;
    }
    auto on_surface = [&](const ViewImage& v, std::size_t i) {
      return v.planes[kValid][i] != 0.0f && std::abs(v.planes[kPY][i] - k.surface_y) < 1e-4f;
    };
    float lo = 1.0f, hi = 0.0f;
    for (std::size_t i = 0; i < a.gbuffer.texels(); ++i) {
      if (!on_surface(a.gbuffer, i)) continue;
      lo = std::min(lo, a.gbuffer.planes[kRoughness][i]);
      hi = std::max(hi, a.gbuffer.planes[kRoughness][i]);
    }
    EXPECT_GT(hi, 1.3f * lo) << "roughness on the surface " << lo << " .. " << hi;
    // Mean |log| ratio of the diffuse flux of horizontal neighbours on the surface: the plain
    // surface has only the spot's smooth cos^3 falloff.
    auto roughness_of_flux = [&](const ViewImage& r) {
      double sum = 0.0;
      std::size_t pairs = 0;
      for (uint32_t y = 0; y < r.height; ++y) {
        for (uint32_t x = 0; x + 1 < r.width; ++x) {
          const std::size_t i = std::size_t{y} * r.width + x;
          const float f0 = r.planes[kDG][i], f1 = r.planes[kDG][i + 1];
          if (!on_surface(r, i) || !on_surface(r, i + 1) || f0 <= 0.0f || f1 <= 0.0f) continue;
          sum += std::abs(std::log(double{f0} / double{f1}));
          ++pairs;
        }
      }
      return pairs > 0 ? sum / static_cast<double>(pairs) : 0.0;
    };
    const double detail_variation = roughness_of_flux(a.rsm), plain_variation = roughness_of_flux(flat.rsm);
    std::printf("%s: light-view neighbour flux variation %.4f with detail, %.4f plain\n", k.scene, detail_variation,
                plain_variation);
    EXPECT_GT(detail_variation, 2.0 * plain_variation);
  }
}

}  // namespace
}  // namespace vsgl
