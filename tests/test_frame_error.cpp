// The image error of one frame (DESIGN.md §11a.1, quality/frame_error.hpp), a series' summary over
// frames (core/statistics.hpp) and each frame's flicker deviation, on inputs with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "harness/core/error.hpp"
#include "harness/core/statistics.hpp"
#include "harness/quality/frame_error.hpp"
#include "harness/quality/quality_metrics.hpp"

namespace vsgl {
namespace {

glm::vec4 grey_pixel(float g) { return glm::vec4(g, g, g, 1.0f); }

// A 16 x 8 image of one grey level, with one pixel without a surface.
RadianceImage flat_image(float g) {
  RadianceImage img{16, 8, std::vector<glm::vec4>(128, grey_pixel(g))};
  img.pixels[5] = glm::vec4(0.0f);
  return img;
}

TEST(FrameError, TheReferenceItselfHasNoError) {
  const RadianceImage ref = flat_image(0.5f);
  const FrameImageError e = frame_image_error(ref, ref, {});
  EXPECT_EQ(e.rel_mse, 0.0);
  EXPECT_EQ(e.relative_rmse, 0.0);
  EXPECT_EQ(e.scaled_rmse, 0.0);
  EXPECT_DOUBLE_EQ(e.scale, 1.0);
  EXPECT_EQ(e.flip, 0.0);
  EXPECT_EQ(e.p99_pixel_error, 0.0);
  EXPECT_EQ(e.max_pixel_error, 0.0);
}

// A frame twice as bright as the reference is all bias: the scale 1/2 removes its whole error.
TEST(FrameError, AGlobalScaleIsBiasTheScaledErrorRemoves) {
  const RadianceImage ref = flat_image(0.5f), twice = flat_image(1.0f);
  const FrameImageError e = frame_image_error(twice, ref, {});
  EXPECT_NEAR(e.relative_rmse, 1.0, 1e-12);
  EXPECT_NEAR(e.scale, 0.5, 1e-12);
  EXPECT_NEAR(e.scaled_rmse, 0.0, 1e-12);
  // (dY)^2 / (Y^2 + 0.01 Y^2) with dY = Y at every pixel.
  EXPECT_NEAR(e.rel_mse, 1.0 / 1.01, 1e-6);
  EXPECT_NEAR(e.p99_pixel_error, 1.0, 1e-6);
  EXPECT_NEAR(e.max_pixel_error, 1.0, 1e-6);
  EXPECT_GT(e.flip, 0.0);
  EXPECT_LE(e.flip, 1.0);
}

TEST(FrameError, OneBrightPixelIsTheTail) {
  const RadianceImage ref = flat_image(1.0f);
  RadianceImage frame = ref;
  frame.pixels[40] = grey_pixel(11.0f);  // |dY| / mean Y = 10 at one of 127 surface pixels
  const FrameImageError e = frame_image_error(frame, ref, {});
  EXPECT_NEAR(e.max_pixel_error, 10.0, 1e-5);
  // Type-7 99th percentile of 126 zeros and one 10: h = 126 * 0.99 = 124.74, between two zeros.
  EXPECT_EQ(e.p99_pixel_error, 0.0);
  EXPECT_NEAR(e.rel_mse, 100.0 / 1.01 / 127.0, 1e-6);
  EXPECT_LT(e.scale, 1.0);
  EXPECT_LT(e.scaled_rmse, e.relative_rmse);
}

TEST(FrameError, ABlackFrameHasScaleZeroAndBadInputIsRefused) {
  const RadianceImage ref = flat_image(0.5f);
  const FrameImageError e = frame_image_error(flat_image(0.0f), ref, {});
  EXPECT_EQ(e.scale, 0.0);
  EXPECT_NEAR(e.scaled_rmse, 1.0, 1e-12);
  EXPECT_NEAR(e.relative_rmse, 1.0, 1e-12);
  EXPECT_THROW(frame_image_error(RadianceImage{1, 1, {grey_pixel(1.0f)}}, ref, {}), InputError);
  EXPECT_THROW(frame_image_error(ref, flat_image(0.0f), {}), InputError);
}

TEST(SeriesSummary, MeanNinetyFifthPercentileAndMaximum) {
  // A per-frame series is summarized by core's summarize, like every other set of values.
  std::vector<double> v;
  for (int i = 20; i >= 1; --i) v.push_back(i);  // unsorted on purpose
  const SampleStats s = summarize(v);
  EXPECT_DOUBLE_EQ(s.mean, 10.5);
  EXPECT_NEAR(s.p95, 1.0 + 19.0 * 0.95, 1e-12);  // type 7: 1 + (n - 1) p on 1..20
  EXPECT_NEAR(s.p99, 1.0 + 19.0 * 0.99, 1e-12);
  EXPECT_DOUBLE_EQ(s.max, 20.0);
  const std::vector<double> two{3.0, 5.0};
  EXPECT_DOUBLE_EQ(summarize(two).p95, 3.0 + 2.0 * 0.95);
  EXPECT_THROW(summarize(std::vector<double>{3.0}), std::invalid_argument);  // no standard deviation
  EXPECT_THROW(summarize(std::vector<double>{1.0, NAN}), std::invalid_argument);
}

TEST(FrameDeviation, EachFramesShareOfTheFlicker) {
  // Pixel A: 1 then 3 (mean 2); pixel B: 2 both frames. delta_f = |Y_f(A) - 2| / (2 + 2) = 1/4.
  FlickerAccumulator acc;
  const RadianceImage ref{2, 1, {grey_pixel(2.0f), grey_pixel(2.0f)}};
  acc.add_frame(RadianceImage{2, 1, {grey_pixel(1.0f), grey_pixel(2.0f)}}, 1.0, ref);
  acc.add_frame(RadianceImage{2, 1, {grey_pixel(3.0f), grey_pixel(2.0f)}}, 1.0, ref);
  const std::vector<double> d = acc.frame_deviations();
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NEAR(d[0], 0.25, 1e-6);
  EXPECT_NEAR(d[1], 0.25, 1e-6);
  // The error Y - Yref is -1 then +1 at A (mean 0), 0 at B; over sum_p mean Yref = 4.
  const std::vector<double> e = acc.error_frame_deviations();
  EXPECT_NEAR(e[0], 0.25, 1e-6);
  EXPECT_NEAR(e[1], 0.25, 1e-6);
  FlickerAccumulator same;
  for (int f = 0; f < 3; ++f) same.add_frame(ref, 1.0);
  for (double v : same.frame_deviations()) EXPECT_EQ(v, 0.0);
  EXPECT_THROW((void)same.error_frame_deviations(), InputError);  // no references
}

}  // namespace
}  // namespace vsgl
