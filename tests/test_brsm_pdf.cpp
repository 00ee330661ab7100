// The BRSM PDF (DESIGN.md §8): equals its CPU twin texel by texel, is deterministic, and concentrates
// its mass where the camera sees the lit surfaces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gpu_test.hpp"
#include "harness/scene/brsm_pdf.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/scene/scene.hpp"
#include "harness/capture/view_matrices.hpp"

namespace vsgl {
namespace {

class BrsmPdfTest : public test::GpuTest {
 protected:
  Capture record(const std::string& scene, RecordSizes sizes) {
    CaptureRecorder recorder(device());
    return recorder.record(make_scene(scene), sizes, 0, 1);
  }
  std::vector<VsglRecord> camera_vsgls(const Capture& c, uint32_t n) {
    const DeviceView view = upload_view(device(), c, ViewKind::kCamera);
    FisParams p;
    p.vsgl_count = n;
    p.pyramid = PyramidPath::kBuffer;  // what build_brsm_pdf uses (the PDF is recorded data)
    FisGenerator gen(device(), view, FisVariant::kModified, p);
    run_untimed(device(), gen);
    return download_vector<VsglRecord>(device(), gen.vsgls(), n);
  }
};

TEST_F(BrsmPdfTest, MatchesTheCpuTwinAndIsDeterministic) {
  Capture a = record("tiny", {96, 64, 32});
  const BrsmBuild build = build_brsm_pdf(device(), a, 512);
  EXPECT_EQ(build.camera_vsgls, 512u);
  EXPECT_GT(build.gpu_ms, 0.0);
  EXPECT_TRUE(a.rsm.has_pdf);
  const auto cams = camera_vsgls(a, 512);
  for (uint32_t y = 0; y < a.rsm.height; ++y)
    for (uint32_t x = 0; x < a.rsm.width; ++x) {
      const float expected = brsm_texel_weight(a.rsm, x, y, a.meta.light.position, cams);
      ASSERT_NEAR(a.rsm.at(kPdf, x, y), expected, 1e-3f * expected + 1e-12f) << "texel " << x << "," << y;
    }
  Capture b = record("tiny", {96, 64, 32});
  build_brsm_pdf(device(), b, 512);
  EXPECT_EQ(plane_hash(a.rsm.planes[kPdf]), plane_hash(b.rsm.planes[kPdf]));
}

// DESIGN.md §10.1: a device that cannot bind the buffer pyramid builds the PDF on the texture path
// and the capture records which path it took. The limit is forced so that a G-buffer layer binds
// (96x64 texels) and the buffer pyramid over its 128^2 square does not.
TEST_F(BrsmPdfTest, TakesTheTexturePathWhereTheBufferPyramidCannotBind) {
  Capture on_buffer = record("tiny", {96, 64, 32});
  Capture on_texture = on_buffer;
  build_brsm_pdf(device(), on_buffer, 512);
  EXPECT_EQ(on_buffer.meta.brsm_pyramid, PyramidPath::kBuffer);

  DeviceInfo forced = device().info();
  forced.limits.storage_buffer_range = 96 * 64 * sizeof(glm::vec4);
  Device limited(test::shared_context().instance(), forced);
  build_brsm_pdf(limited, on_texture, 512);
  EXPECT_EQ(on_texture.meta.brsm_pyramid, PyramidPath::kTexture);
  EXPECT_TRUE(on_texture.rsm.has_pdf);
  // The same PDF up to the texture path's filter precision: its mass within 1 % (measured 8e-5 on
  // lavapipe, 6e-4 on SwiftShader).
  double buffer_mass = 0, texture_mass = 0;
  for (std::size_t i = 0; i < on_buffer.rsm.texels(); ++i) {
    buffer_mass += double{on_buffer.rsm.planes[kPdf][i]};
    texture_mass += double{on_texture.rsm.planes[kPdf][i]};
  }
  EXPECT_GT(buffer_mass, 0.0);
  EXPECT_NEAR(texture_mass / buffer_mass, 1.0, 0.01);
}

// The PDF follows the camera. Same light (same RSM flux), two cameras: looking down the hall at
// the lit floor and columns, and turned around to face the end wall behind it. Importance per watt
// of the lit texels drops when the lit area is behind the camera (measured 1.7x on lavapipe), and
// for the camera facing the hall the PDF's mass moves from the flux centroid towards the surfaces
// it sees close up (+z, measured +1.24 m).
TEST_F(BrsmPdfTest, ConcentratesWhereTheCameraSeesTheLitSurfaces) {
  struct Stats {
    double importance_per_watt, pdf_centroid_z, flux_centroid_z;
  };
  auto measure = [&](const Scene& scene) {
    CaptureRecorder recorder(device());
    Capture c = recorder.record(scene, {160, 90, 48}, 0, 1);
    build_brsm_pdf(device(), c, 1024);
    double q = 0, w = 0, qz = 0, wz = 0;
    const auto& p = c.rsm.planes;
    for (std::size_t i = 0; i < c.rsm.texels(); ++i) {
      const double wi = double{p[kDR][i]} + double{p[kDG][i]} + double{p[kDB][i]} + double{p[kSR][i]} +
                        double{p[kSG][i]} + double{p[kSB][i]};
      const double qi = p[kPdf][i];
      q += qi;
      w += wi;
      qz += qi * double{p[kPZ][i]};
      wz += wi * double{p[kPZ][i]};
    }
    return Stats{q / w, qz / q, wz / w};
  };
  const Scene facing = make_scene("atrium");
  Scene turned = facing;
  turned.camera.target = turned.camera.position + (turned.camera.position - facing.camera.target);
  const Stats a = measure(facing), b = measure(turned);
  std::printf("facing: importance/W %g, PDF centroid z %.2f (flux %.2f); turned: importance/W %g, PDF centroid z "
              "%.2f (flux %.2f)\n",
              a.importance_per_watt, a.pdf_centroid_z, a.flux_centroid_z, b.importance_per_watt, b.pdf_centroid_z,
              b.flux_centroid_z);
  EXPECT_GT(a.importance_per_watt, 1.3 * b.importance_per_watt);
  EXPECT_GT(a.pdf_centroid_z - a.flux_centroid_z, 0.5);
}

}  // namespace
}  // namespace vsgl
