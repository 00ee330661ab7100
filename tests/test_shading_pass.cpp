// The shading pass (DESIGN.md §8 (a)) and its pictures: the GPU radiance equals the CPU twin pixel by
// pixel, the stride picks every k-th G-buffer texel, pixels without geometry are black; tone
// mapping is monotonic and the PNG coding round-trips bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <unistd.h>

#include "cli_runner.hpp"
#include "gpu_test.hpp"
#include "harness/scene/brsm_pdf.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/core/error.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/quality/png_image.hpp"
#include "harness/scene/scene.hpp"
#include "harness/quality/shading_pass.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

class ShadingPassTest : public test::GpuTest {
 protected:
  // The tiny scene with its BRSM PDF, and a band of G-buffer rows and a block marked as
  // background so the "no geometry -> black" rule is exercised wherever the scene covers all.
  Capture tiny_capture() {
    CaptureRecorder recorder(device());
    Capture c = recorder.record(make_scene("tiny"), RecordSizes{96, 64, 64}, 0, 1);
    build_brsm_pdf(device(), c, 512);
    for (uint32_t y = 0; y < c.gbuffer.height; ++y)
      for (uint32_t x = 0; x < c.gbuffer.width; ++x)
        if (y < 3 || (x >= 40 && x < 52 && y >= 20 && y < 30)) c.gbuffer.at(kValid, x, y) = 0.0f;
    return c;
  }
};

TEST_F(ShadingPassTest, MatchesTheCpuTwinAndBlackWhereNoGeometry) {
  const Capture capture = tiny_capture();
  const DeviceView camera = upload_view(device(), capture, ViewKind::kCamera);
  const DeviceView light = upload_view(device(), capture, ViewKind::kLight);
  FisParams params;
  params.vsgl_count = 256;
  FisGenerator gen(device(), light, FisVariant::kModified, params);
  run_untimed(device(), gen);
  const auto vsgls = download_vector<VsglRecord>(device(), gen.vsgls(), params.vsgl_count);

  const RadianceImage full = shade_camera_view(device(), camera, gen.vsgls(), params.vsgl_count, 1);
  ASSERT_EQ(full.width, 96u);
  ASSERT_EQ(full.height, 64u);
  ASSERT_EQ(full.pixels.size(), 96u * 64u);
  float brightest = 0.0f;
  uint32_t lit = 0, background = 0;
  for (uint32_t y = 0; y < full.height; ++y)
    for (uint32_t x = 0; x < full.width; ++x) {
      const glm::vec4 p = full.pixels[y * full.width + x];
      if (capture.gbuffer.at(kValid, x, y) <= 0.5f) {
        ++background;
        ASSERT_EQ(p, glm::vec4(0.0f)) << "pixel " << x << "," << y << " has no geometry but is not black";
        continue;
      }
      ASSERT_EQ(p.a, 1.0f);
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(p[c]) && p[c] >= 0.0f) << "pixel " << x << "," << y;
      brightest = std::max({brightest, p.r, p.g, p.b});
      if (p.r + p.g + p.b > 0.0f) ++lit;
    }
  EXPECT_GE(background, 3u * 96u + 120u);
  EXPECT_GT(lit, 1000u) << "the VSGLs light almost nothing: the comparison below would be vacuous";
  ASSERT_GT(brightest, 0.0f);

  // Every 7th pixel (and the corners) against the CPU twin, which sums the VSGLs in the same order.
  uint32_t compared = 0;
  for (uint32_t i = 0; i < full.pixels.size(); i += 7) {
    const uint32_t x = i % full.width, y = i / full.width;
    const glm::vec4 expected = shade_pixel_reference(capture.gbuffer, x, y, camera.source_position, vsgls);
    const glm::vec4 got = full.pixels[i];
    for (int c = 0; c < 4; ++c)
      ASSERT_NEAR(got[c], expected[c], 2e-4f * std::abs(expected[c]) + 1e-6f * brightest)
          << "pixel " << x << "," << y << " channel " << c;
    ++compared;
  }
  EXPECT_GT(compared, 800u);

  // Stride 3: ceil(96/3) x ceil(64/3) pixels, pixel (i, j) = G-buffer texel (3i, 3j).
  const RadianceImage preview = shade_camera_view(device(), camera, gen.vsgls(), params.vsgl_count, 3);
  ASSERT_EQ(preview.width, 32u);
  ASSERT_EQ(preview.height, 22u);
  for (uint32_t j = 0; j < preview.height; ++j)
    for (uint32_t i = 0; i < preview.width; ++i) {
      const glm::vec4 a = preview.pixels[j * preview.width + i];
      const glm::vec4 b = full.pixels[(3 * j) * full.width + 3 * i];
      for (int c = 0; c < 4; ++c) ASSERT_NEAR(a[c], b[c], 1e-6f * std::abs(b[c])) << "preview " << i << "," << j;
    }
}

// The converged reference shades 10^5 VSGLs in chunks of dispatches; a later chunk adds to the sum
// the previous one stored, in the same index order, so the image is the one-dispatch image bit for
// bit, whatever the chunk size (a whole tile, several, or a count that does not divide N).
TEST_F(ShadingPassTest, ChunkedDispatchesGiveTheSameImage) {
  const Capture capture = tiny_capture();
  const DeviceView camera = upload_view(device(), capture, ViewKind::kCamera);
  const DeviceView light = upload_view(device(), capture, ViewKind::kLight);
  FisParams params;
  params.vsgl_count = 700;
  FisGenerator gen(device(), light, FisVariant::kTok15, params);
  run_untimed(device(), gen);
  const RadianceImage one = shade_camera_view(device(), camera, gen.vsgls(), params.vsgl_count, 2, 700);
  for (uint32_t chunk : {256u, 300u, 512u}) {
    SCOPED_TRACE(chunk);
    const RadianceImage chunked = shade_camera_view(device(), camera, gen.vsgls(), params.vsgl_count, 2, chunk);
    ASSERT_EQ(chunked.pixels.size(), one.pixels.size());
    EXPECT_TRUE(chunked.pixels == one.pixels);
  }
  // More VSGLs than one binding holds (maxStorageBufferRange): the records are bound a window of
  // whole chunks at a time, to the same image.
  for (const auto& [chunk, binding] : {std::pair{256u, 512u}, {300u, 600u}, {256u, 300u}}) {
    SCOPED_TRACE(std::to_string(chunk) + " per dispatch, " + std::to_string(binding) + " per binding");
    const RadianceImage windowed =
        shade_camera_view(device(), camera, gen.vsgls(), params.vsgl_count, 2, chunk, binding);
    EXPECT_TRUE(windowed.pixels == one.pixels);
  }
  float brightest = 0.0f;
  for (const glm::vec4& p : one.pixels) brightest = std::max(brightest, p.r);
  EXPECT_GT(brightest, 0.0f);
}

TEST_F(ShadingPassTest, BindingWindowsHoldWholeChunksWithinTheRange) {
  EXPECT_EQ(binding_window_vsgls(device(), 1000, 256, 0), 1000u);  // fits the device's range at once
  EXPECT_EQ(binding_window_vsgls(device(), 1000, 256, 1000), 1000u);
  EXPECT_EQ(binding_window_vsgls(device(), 1000, 256, 700), 512u);  // two whole chunks
  EXPECT_EQ(binding_window_vsgls(device(), 1000, 256, 256), 256u);
  EXPECT_THROW(binding_window_vsgls(device(), 1000, 256, 255), DeviceLimitError);  // not one chunk
  // The device's own limit: the records of one binding are at most maxStorageBufferRange bytes.
  const uint64_t range = device().info().limits.storage_buffer_range;
  const uint64_t more = range / sizeof(VsglRecord) + 1000;
  if (more <= UINT32_MAX) {
    const uint32_t window = binding_window_vsgls(device(), static_cast<uint32_t>(more), 256, 0);
    EXPECT_LE(uint64_t{window} * sizeof(VsglRecord), range);
    EXPECT_EQ(window % 256u, 0u);
    EXPECT_GT(window, 0u);
  }
}

TEST(ShadingChunks, ChunksHoldTheEvaluationBudgetInWholeTiles) {
  EXPECT_EQ(shade_chunk_vsgls(uint64_t{1} << 15), 1024u);  // 2^25 / 2^15
  EXPECT_EQ(shade_chunk_vsgls(480u * 272u) % 256u, 0u);    // whole tiles of 16 x 16
  EXPECT_LE(uint64_t{shade_chunk_vsgls(480u * 272u)} * 480u * 272u, kShadeEvaluationsPerDispatch);
  EXPECT_EQ(shade_chunk_vsgls(uint64_t{1920} * 1088 * 64), 256u);  // never less than a tile
}

TEST_F(ShadingPassTest, RejectsBadArguments) {
  const Capture capture = tiny_capture();
  const DeviceView camera = upload_view(device(), capture, ViewKind::kCamera);
  const DeviceView light = upload_view(device(), capture, ViewKind::kLight);
  FisParams params;
  params.vsgl_count = 16;
  FisGenerator gen(device(), light, FisVariant::kTok15, params);
  EXPECT_THROW(shade_camera_view(device(), camera, gen.vsgls(), 16, 0), InputError);      // stride 0
  EXPECT_THROW(shade_camera_view(device(), light, gen.vsgls(), 16, 1), InputError);       // not the camera
  EXPECT_THROW(shade_camera_view(device(), camera, gen.vsgls(), 17, 1), InputError);      // too few records
  EXPECT_THROW(shade_camera_view(device(), camera, gen.vsgls(), 0, 1), InputError);       // nothing to shade
}

TEST(ShadingPicture, ToneMappingIsMonotonicAndSpansTheRange) {
  const float exposure = 2.5f;
  EXPECT_EQ(tone_map_value(0.0f, exposure), 0);
  EXPECT_EQ(tone_map_value(-1.0f, exposure), 0);
  EXPECT_EQ(tone_map_value(1.0f / exposure, exposure), 255);
  EXPECT_EQ(tone_map_value(100.0f, exposure), 255);
  EXPECT_EQ(tone_map_value(0.5f / exposure, exposure), 188);  // sRGB(0.5) = 0.7354 -> 187.5 -> 188
  int previous = 0;
  int distinct = 1;
  for (int i = 0; i <= 20000; ++i) {
    const float v = static_cast<float>(i) * (1.2f / exposure) / 20000.0f;
    const int code = tone_map_value(v, exposure);
    ASSERT_GE(code, previous) << "at linear value " << v;
    if (code != previous) ++distinct;
    previous = code;
  }
  EXPECT_EQ(distinct, 256);  // every 8-bit code is reached on the way up
}

TEST(ShadingPicture, AutoExposureMapsThe99thPercentileAndIgnoresBackground) {
  RadianceImage image;
  image.width = 110;
  image.height = 1;
  for (int i = 1; i <= 100; ++i) image.pixels.emplace_back(glm::vec3(static_cast<float>(i)), 1.0f);  // grey: Y = i
  for (int i = 0; i < 10; ++i) image.pixels.emplace_back(glm::vec3(1e6f), 0.0f);  // no geometry
  EXPECT_FLOAT_EQ(auto_exposure(image), 0.8f / 99.0f);
  EXPECT_FLOAT_EQ(auto_exposure(image, 0.5f, 0.5f), 0.5f / 50.0f);
  RadianceImage dark;
  dark.width = 2;
  dark.height = 1;
  dark.pixels = {glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), glm::vec4(0.0f)};
  EXPECT_EQ(auto_exposure(dark), 1.0f);
}

TEST(ShadingPicture, NonFiniteRadianceIsAnErrorNotAColour) {
  RadianceImage image;
  image.width = 2;
  image.height = 1;
  image.pixels = {glm::vec4(1.0f), glm::vec4(std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f, 1.0f)};
  EXPECT_THROW(tone_map(image, 1.0f), std::runtime_error);
  image.pixels[1] = glm::vec4(0.0f, std::numeric_limits<float>::infinity(), 0.0f, 1.0f);
  EXPECT_THROW(tone_map(image, 1.0f), std::runtime_error);
}

TEST(ShadingPicture, PngRoundTripsAndIsDeterministic) {
  RadianceImage image;
  image.width = 37;  // odd sizes: no row padding assumptions
  image.height = 23;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x)
      image.pixels.emplace_back(static_cast<float>(x) / 36.0f, static_cast<float>(y) / 22.0f,
                                static_cast<float>((x * 7 + y * 13) % 17) / 16.0f, 1.0f);
  const Rgb8Image picture = tone_map(image, 1.0f);
  const std::vector<char> png = encode_png(picture);
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(std::string(png.begin() + 1, png.begin() + 4), "PNG");
  EXPECT_EQ(encode_png(picture), png);
  const Rgb8Image decoded = decode_png(png);
  EXPECT_EQ(decoded.width, picture.width);
  EXPECT_EQ(decoded.height, picture.height);
  EXPECT_EQ(decoded.rgb, picture.rgb);

  const test::TempDir dir_temp("png");
  const std::filesystem::path& dir = dir_temp.path();
  const auto path = dir / "picture.png";
  write_png_atomic(path, picture);
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> on_disk((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(on_disk, png);

  const std::vector<char> garbage = {'n', 'o', 't', ' ', 'a', ' ', 'p', 'n', 'g'};
  EXPECT_THROW(decode_png(garbage, "garbage.png"), InputError);
}

// `vsgl-bench shade` as a user meets it: one PNG per generator at the stride's size, the same
// bytes on a second run, and usage errors for an unknown generator or a missing capture.
TEST(ShadingCli, WritesOnePngPerGeneratorDeterministically) {
  const test::TempDir dir_temp("cli_shade");
  const std::filesystem::path& dir = dir_temp.path();
  const auto capture = dir / "tiny";
  const auto rec = test::run_cli("record --scene tiny --gbuffer 96x64 --rsm 32 --out " + capture.string());
  ASSERT_EQ(rec.exit_code, 0) << rec.output;
  // Without visibility (the default is the ISM's, tests/test_shade_visibility.cpp).
  const std::string shade = "shade --capture " + capture.string() + " --vsgls 64 --stride 2 --visibility none" +
                            (test::test_validation() ? " --validate" : "") + " --out ";
  const auto first = test::run_cli(shade + (dir / "a").string());
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_NE(first.output.find("no visibility"), std::string::npos) << first.output;
  const auto second = test::run_cli(shade + (dir / "b").string());
  ASSERT_EQ(second.exit_code, 0) << second.output;
  const auto read = [](const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  for (const char* generator : {"fis_tok15", "fis_modified"}) {
    const std::string name = std::string("shade_tiny_") + generator + ".png";
    const auto bytes = read(dir / "a" / name);
    ASSERT_FALSE(bytes.empty()) << name << " missing; output:\n" << first.output;
    const Rgb8Image picture = decode_png(bytes, name);
    EXPECT_EQ(picture.width, 48u);
    EXPECT_EQ(picture.height, 32u);
    EXPECT_TRUE(std::any_of(picture.rgb.begin(), picture.rgb.end(), [](uint8_t v) { return v > 0; }));
    EXPECT_EQ(read(dir / "b" / name), bytes) << name << " differs between two runs";
  }
  const auto unknown = test::run_cli("shade --capture " + capture.string() + " --generators fis_nope");
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("fis_nope"), std::string::npos) << unknown.output;
  EXPECT_EQ(test::run_cli("shade --stride 2").exit_code, 2);
  const auto missing = test::run_cli("shade --capture " + (dir / "nowhere").string());
  EXPECT_EQ(missing.exit_code, 3) << missing.output;
}

}  // namespace
}  // namespace vsgl
