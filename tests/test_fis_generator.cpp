// The FIS generators on the GPU against their CPU reference (DESIGN.md §11): the pyramid built on the
// device equals the CPU mip chain of the same level 0 bit for bit, the sampler picks the same
// texels, and every VSGL (level, density, power, moments) agrees to float rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gpu_test.hpp"
#include "tiny_capture.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/core/error.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/reference/fis_reference.hpp"

namespace vsgl {
namespace {

class FisGeneratorTest : public test::GpuTest {
 protected:
  Capture tiny_capture() { return test::record_tiny_with_flux_pdf(device()); }

  void run(FisGenerator& gen) { run_untimed(device(), gen); }

  MomentPyramids download_pyramids(const FisGenerator& gen, const VirtualSquare& sq) {
    const auto all = gen.download_pyramid(device());
    MomentPyramids out;
    for (uint32_t layer = 0; layer < kMomentLayerCount; ++layer) {
      out[layer].square = sq;
      out[layer].texels.assign(all.begin() + layer * sq.total_texels(), all.begin() + (layer + 1) * sq.total_texels());
    }
    return out;
  }

  static std::vector<glm::vec4> level0(const MipPyramid& p) {
    return {p.texels.begin(), p.texels.begin() + p.square.level_texels(0)};
  }

  void check_view(const Capture& capture, ViewKind kind, FisVariant variant, uint32_t N) {
    SCOPED_TRACE(std::string(view_name(kind)) + " " + fis_variant_name(variant));
    const DeviceView view = upload_view(device(), capture, kind);
    FisParams params;
    params.vsgl_count = N;
    params.pyramid = PyramidPath::kBuffer;  // bit-exact with the CPU reference
    FisGenerator gen(device(), view, variant, params);
    run(gen);
    const VirtualSquare& sq = view.square;
    const auto gpu = download_pyramids(gen, sq);

    // "additional": level 0 against the CPU moments (transcendental maths: float tolerance).
    const auto cpu_moments = reference_moments(capture.view(kind), view.source_position);
    for (uint32_t layer = 0; layer < kMomentLayerCount; ++layer)
      for (uint32_t i = 0; i < sq.level_texels(0); ++i)
        for (int c = 0; c < 4; ++c) {
          const float a = gpu[layer].texels[i][c], b = cpu_moments[layer][i][c];
          ASSERT_NEAR(a, b, 1e-5f * std::max(1.0f, std::abs(b))) << "layer " << layer << " texel " << i;
        }
    // "mipmapping": bit-exact against the CPU chain of the same level 0.
    MomentPyramids cpu;
    for (uint32_t layer = 0; layer < kMomentLayerCount; ++layer) {
      cpu[layer] = MipPyramid::build(level0(gpu[layer]), sq.width, sq.height);
      ASSERT_EQ(cpu[layer].texels.size(), gpu[layer].texels.size());
      for (std::size_t i = 0; i < cpu[layer].texels.size(); ++i)
        ASSERT_EQ(cpu[layer].texels[i], gpu[layer].texels[i]) << "layer " << layer << " element " << i;
    }
    // "filtered_sampling": same kernel centres, levels, densities and VSGLs.
    const auto expected = reference_fis(cpu, variant, params);
    const auto got = download_vector<VsglRecord>(device(), gen.vsgls(), N);
    const auto samples = reference_samples(cpu[2], N, 0);
    for (uint32_t i = 0; i < N; ++i) {
      SCOPED_TRACE("VSGL " + std::to_string(i));
      const glm::vec2 x(got[i].center_pdf);
      ASSERT_EQ(glm::uvec2(x * static_cast<float>(sq.size)), samples[i].texel);
      ASSERT_NEAR(x.x, samples[i].x.x, 1e-7f);
      ASSERT_NEAR(x.y, samples[i].x.y, 1e-7f);
      EXPECT_NEAR(got[i].axis_level.w, expected[i].axis_level.w, 1e-3f) << "level";
      EXPECT_NEAR(got[i].center_pdf.z, expected[i].center_pdf.z, 1e-4f * expected[i].center_pdf.z) << "density";
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[i].power_sharpness[c], expected[i].power_sharpness[c],
                    2e-3f * std::abs(expected[i].power_sharpness[c]) + 1e-9f)
            << "power channel " << c;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[i].specular_power[c], expected[i].specular_power[c],
                    2e-3f * std::abs(expected[i].specular_power[c]) + 1e-9f)
            << "specular power channel " << c;
        EXPECT_NEAR(got[i].position_variance[c], expected[i].position_variance[c], 1e-3f) << "mu";
        EXPECT_NEAR(got[i].normal_length[c], expected[i].normal_length[c], 1e-4f) << "normal";
      }
    }
  }
};

TEST_F(FisGeneratorTest, MatchesTheCpuReferenceOnBothViews) {
  const Capture capture = tiny_capture();
  for (FisVariant variant : {FisVariant::kTok15, FisVariant::kModified}) {
    check_view(capture, ViewKind::kCamera, variant, 256);
    check_view(capture, ViewKind::kLight, variant, 128);
  }
}

// DESIGN.md §6.1a: the texture path. Every mipmapping strategy builds the CPU chain of the device's
// level 0 (the compute ones bit for bit; the blit, whose samples land between the children only
// to subTexelPrecisionBits, each texel within blit_chain_error_ratio's bound of its children's
// mean); the kernel centres are the CPU's exactly (texelFetch), and every
// power is the CPU's at the device's level within the bound the device's filter precision allows
// (fetch_error_bound) plus 1e-4 relative. The tiny G-buffer's square (128, L = 7) makes the
// single-pass downsampler hand over to its last group; the RSM's (64, L = 6) fits one group.
TEST_F(FisGeneratorTest, TexturePathMatchesTheCpuReferenceWithEveryMipStrategy) {
  const Capture capture = tiny_capture();
  const FilterPrecision precision{device().info().sub_texel_precision_bits, device().info().mipmap_precision_bits};
  for (ViewKind kind : {ViewKind::kCamera, ViewKind::kLight}) {
    const DeviceView view = upload_view(device(), capture, kind);
    const VirtualSquare& sq = view.square;
    for (MipStrategy m : {MipStrategy::kSinglePass, MipStrategy::kBlit, MipStrategy::kPerLevel})
      for (FisVariant variant : {FisVariant::kTok15, FisVariant::kModified}) {
        SCOPED_TRACE(std::string(view_name(kind)) + " " + mip_strategy_name(m) + " " + fis_variant_name(variant));
        FisParams params;
        params.vsgl_count = kind == ViewKind::kCamera ? 256 : 128;
        params.pyramid = PyramidPath::kTexture;
        params.mipmapping = m;
        FisGenerator gen(device(), view, variant, params);
        ASSERT_EQ(gen.pyramid_path(), PyramidPath::kTexture);
        run(gen);
        const auto gpu = download_pyramids(gen, sq);
        MomentPyramids cpu;
        for (uint32_t layer = 0; layer < kMomentLayerCount; ++layer) {
          cpu[layer] = MipPyramid::build(level0(gpu[layer]), sq.width, sq.height);
          if (m == MipStrategy::kBlit) {
            EXPECT_LE(blit_chain_error_ratio(gpu[layer], precision), 1.0) << "layer " << layer;
            continue;
          }
          for (std::size_t i = 0; i < cpu[layer].texels.size(); ++i)
            ASSERT_EQ(cpu[layer].texels[i], gpu[layer].texels[i]) << "layer " << layer << " element " << i;
        }
        // Later passes against the pyramid they read (the blit's own, checked just above).
        const MomentPyramids& read = m == MipStrategy::kBlit ? gpu : cpu;
        const auto got = download_vector<VsglRecord>(device(), gen.vsgls(), params.vsgl_count);
        const auto samples = reference_samples(read[2], params.vsgl_count, 0);
        for (uint32_t i = 0; i < params.vsgl_count; ++i) {
          SCOPED_TRACE("VSGL " + std::to_string(i));
          const glm::vec2 x(got[i].center_pdf);
          ASSERT_EQ(glm::uvec2(x * static_cast<float>(sq.size)), samples[i].texel);
          ASSERT_NEAR(x.x, samples[i].x.x, 1e-7f);
          ASSERT_NEAR(x.y, samples[i].x.y, 1e-7f);
          const float l = got[i].axis_level.w;
          if (variant == FisVariant::kTok15) {
            EXPECT_NEAR(l, tok15_level(samples[i].pdf, params.vsgl_count, params.K, sq), 1e-4f);
          }
          const auto [expected, bound] = fis_power_bound(variant, read, samples[i], l, params, precision);
          for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[i].power_sharpness[c], expected[c], bound[c] + 1e-4f * std::abs(expected[c]) + 1e-9f)
                << "power channel " << c;
        }
      }
  }
  // The blit chain and the readback use the transfer layouts, not GENERAL (the layer's
  // performance warning InvalidImageLayout; GENERAL can cost compression on GPUs).
  for (const std::string& m : test::shared_context().instance().validation_messages())
    EXPECT_EQ(m.find("InvalidImageLayout"), std::string::npos) << m;
}

TEST_F(FisGeneratorTest, RejectsBadParameters) {
  const Capture capture = tiny_capture();
  const DeviceView view = upload_view(device(), capture, ViewKind::kCamera);
  FisParams p;
  p.vsgl_count = 0;
  EXPECT_THROW(FisGenerator(device(), view, FisVariant::kModified, p), InputError);
  p.vsgl_count = view.samplable_texels + 1;
  EXPECT_THROW(FisGenerator(device(), view, FisVariant::kModified, p), InputError);
  p.vsgl_count = 16;
  p.K = 0.0f;
  EXPECT_THROW(FisGenerator(device(), view, FisVariant::kTok15, p), InputError);
  p.K = -1.0f;
  EXPECT_THROW(FisGenerator(device(), view, FisVariant::kTok15, p), InputError);
}

TEST_F(FisGeneratorTest, AllZeroPdfIsAClearError) {
  Capture capture = tiny_capture();
  std::fill(capture.gbuffer.planes[kPdf].begin(), capture.gbuffer.planes[kPdf].end(), 0.0f);
  try {
    upload_view(device(), capture, ViewKind::kCamera);
    FAIL() << "an all-zero PDF was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("all-zero PDF"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vsgl
