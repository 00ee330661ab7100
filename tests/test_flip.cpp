// harness/quality/flip.hpp: the properties the FLIP paper states (0 for identical images, every
// pixel in [0, 1], symmetric colour and feature terms, larger for larger differences) and a check
// against the published reference implementation on small synthetic images.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>

#include "harness/quality/flip.hpp"

namespace vsgl {
namespace {

// A deterministic noise in [-1, 1] per pixel (an integer hash, so the reference check can draw the
// same images elsewhere).
double pixel_noise(int x, int y) {
  uint32_t v = static_cast<uint32_t>(x) * 73856093u ^ static_cast<uint32_t>(y) * 19349663u;
  v ^= v >> 13;
  v *= 0x5bd1e995u;
  v ^= v >> 15;
  return static_cast<double>(v % 1001u) / 500.0 - 1.0;
}

// Each channel computed in double and stored as float, as RadianceImage holds it.
RadianceImage make_image(int w, int h, const std::function<void(int, int, double*)>& rgb) {
  RadianceImage image;
  image.width = static_cast<uint32_t>(w);
  image.height = static_cast<uint32_t>(h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double c[3];
      rgb(x, y, c);
      image.pixels.emplace_back(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]), 1.0f);
    }
  return image;
}

// The value stored as float, times m (in double), stored as float again.
RadianceImage scaled_by_noise(const RadianceImage& image, double amplitude) {
  RadianceImage out = image;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      glm::vec4& p = out.pixels[y * image.width + x];
      const double m = 1.0 + amplitude * pixel_noise(static_cast<int>(x), static_cast<int>(y));
      for (int c = 0; c < 3; ++c) p[c] = static_cast<float>(static_cast<double>(p[c]) * m);
    }
  return out;
}

constexpr int kW = 32, kH = 24;

RadianceImage gradient() {
  return make_image(kW, kH, [](int x, int y, double* c) {
    c[0] = 2.0 * x / (kW - 1);
    c[1] = static_cast<double>(y) / (kH - 1);
    c[2] = 0.5;
  });
}
// A bright square on a dark ground, its left edge at x = 8 + shift.
RadianceImage square(int shift) {
  return make_image(kW, kH, [shift](int x, int y, double* c) {
    const bool in = x >= 8 + shift && x < 16 + shift && y >= 6 && y < 18;
    c[0] = c[1] = c[2] = in ? 4.0 : 0.05;
  });
}
// Left half red (or green), right half blue.
RadianceImage halves(bool green) {
  return make_image(kW, kH, [green](int x, int, double* c) {
    if (x >= kW / 2) {
      c[0] = 0.1, c[1] = 0.1, c[2] = 1.0;
    } else if (green) {
      c[0] = 0.1, c[1] = 1.0, c[2] = 0.1;
    } else {
      c[0] = 1.0, c[1] = 0.1, c[2] = 0.1;
    }
  });
}
// A grey field, with one bright pixel at (10, 7).
RadianceImage grey(bool spot) {
  return make_image(kW, kH,
                    [spot](int x, int y, double* c) { c[0] = c[1] = c[2] = spot && x == 10 && y == 7 ? 8.0 : 0.2; });
}
// 96 x 64: a soft highlight, a checker of 8-pixel tiles, a vertical ramp.
RadianceImage scene() {
  return make_image(96, 64, [](int x, int y, double* c) {
    const double u = x / 96.0, v = y / 64.0;
    c[0] = 0.3 + 2.5 * std::exp(-((u - 0.3) * (u - 0.3) + (v - 0.4) * (v - 0.4)) * 20);
    c[1] = 0.2 + 0.5 * u * v + ((x / 8 + y / 8) % 2) * 0.3;
    c[2] = 0.1 + 0.8 * v;
  });
}

float at(const FlipResult& r, int x, int y) { return r.error[static_cast<std::size_t>(y) * r.width + x]; }

TEST(Flip, IdenticalImagesGiveZero) {
  for (const RadianceImage& image : {gradient(), square(0), halves(false), scene()}) {
    const FlipResult r = flip_error(image, image, {.exposure = 1.5});
    EXPECT_EQ(r.mean, 0.0);
    for (float e : r.error) EXPECT_EQ(e, 0.0f);
  }
}

TEST(Flip, ErrorLiesInZeroOne) {
  // The largest differences the tone-mapped range allows: black against white, green against blue,
  // and noise at every exposure from dark to burnt out.
  const RadianceImage black = make_image(kW, kH, [](int, int, double* c) { c[0] = c[1] = c[2] = 0.0; });
  const RadianceImage white = make_image(kW, kH, [](int, int, double* c) { c[0] = c[1] = c[2] = 1e6; });
  const RadianceImage green = make_image(kW, kH, [](int, int, double* c) { c[0] = 0, c[1] = 1e6, c[2] = 0; });
  const RadianceImage blue = make_image(kW, kH, [](int, int, double* c) { c[0] = 0, c[1] = 0, c[2] = 1e6; });
  const FlipResult bw = flip_error(black, white);
  const FlipResult gb = flip_error(green, blue);
  for (float e : bw.error) EXPECT_TRUE(e >= 0.0f && e <= 1.0f);
  // Green against blue is the largest colour difference FLIP knows: exactly 1 (to rounding).
  for (float e : gb.error) EXPECT_NEAR(e, 1.0f, 1e-6f);
  for (double exposure : {-8.0, -2.0, 0.0, 3.0, 10.0}) {
    const FlipResult r = flip_error(scene(), scaled_by_noise(scene(), 0.9), {.exposure = exposure});
    for (float e : r.error) EXPECT_TRUE(e >= 0.0f && e <= 1.0f) << e;
    EXPECT_GE(r.mean, 0.0);
    EXPECT_LE(r.mean, 1.0);
  }
}

TEST(Flip, SymmetricInReferenceAndTest) {
  // Both pipelines compare the two images through symmetric distances (HyAB, |Δ edge|, |Δ point|),
  // so swapping reference and test gives the same map.
  const FlipResult ab = flip_error(square(0), square(1), {.exposure = -1, .pixels_per_degree = 30});
  const FlipResult ba = flip_error(square(1), square(0), {.exposure = -1, .pixels_per_degree = 30});
  ASSERT_EQ(ab.error.size(), ba.error.size());
  for (std::size_t i = 0; i < ab.error.size(); ++i) EXPECT_EQ(ab.error[i], ba.error[i]);
}

TEST(Flip, LargerDifferencesScoreHigher) {
  // More noise on the same image: a larger mean error.
  double previous = 0;
  for (double amplitude : {0.05, 0.2, 0.6}) {
    const double mean = flip_error(scene(), scaled_by_noise(scene(), amplitude)).mean;
    EXPECT_GT(mean, previous) << amplitude;
    previous = mean;
  }
  // Viewed from farther (more pixels per degree), the eye's filters blur the noise more: lower.
  EXPECT_LT(flip_error(scene(), scaled_by_noise(scene(), 0.35), {.pixels_per_degree = 120}).mean,
            flip_error(scene(), scaled_by_noise(scene(), 0.35), {.pixels_per_degree = 10}).mean);
}

TEST(Flip, ToneMapping) {
  EXPECT_EQ(aces_filmic(0.0), 0.0);
  // The curve rises and saturates near 2.51 / 2.43 (clamped to 1 in tone_mapped).
  EXPECT_LT(aces_filmic(0.5), aces_filmic(1.0));
  EXPECT_NEAR(aces_filmic(1e9), 2.51 / 2.43, 1e-6);
  // 0.6 x into Narkowicz's fit: at x = 1, v = 0.6: 0.6 (1.506 + 0.03) / (0.6 (1.458 + 0.59) + 0.14).
  EXPECT_NEAR(aces_filmic(1.0), 0.6 * 1.536 / (0.6 * 2.048 + 0.14), 1e-12);
  // An exposure of +1 is twice the radiance; the result is clamped to [0, 1].
  const RadianceImage one = make_image(1, 1, [](int, int, double* c) { c[0] = 0.5, c[1] = 100.0, c[2] = -1.0; });
  const std::vector<glm::dvec3> t = tone_mapped(one, 1.0);
  EXPECT_NEAR(t[0].x, aces_filmic(1.0), 1e-7);
  EXPECT_EQ(t[0].y, 1.0);
  EXPECT_EQ(t[0].z, 0.0);
}

TEST(Flip, RefusesWhatItCannotCompare) {
  RadianceImage small = gradient();
  small.width = 16;
  EXPECT_THROW(flip_error(gradient(), small), std::invalid_argument);  // size disagrees with the pixels
  EXPECT_THROW(flip_error(gradient(), scene()), std::invalid_argument);
  EXPECT_THROW(flip_error(RadianceImage{}, RadianceImage{}), std::invalid_argument);
  RadianceImage nan = gradient();
  nan.pixels[3].g = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(flip_error(gradient(), nan), std::invalid_argument);
  EXPECT_THROW(flip_error(gradient(), gradient(), {.pixels_per_degree = 0}), std::invalid_argument);
  EXPECT_THROW(flip_error(gradient(), gradient(), {.exposure = std::numeric_limits<double>::infinity()}),
               std::invalid_argument);
}

// ---- Against the published reference implementation ------------------------------------------
// Expected values: FLIP.h of NVlabs/flip v1.6 (commit 1eb247cabcf2862c2c8207ab15314304394132b9),
// run on these same images (drawn with the same code, as float), each exposed by 2^exposure, tone
// mapped by its "aces" tone mapper and clamped, then its LDR FLIP (useHDR = false) at the given
// pixels per degree: the mean and a few pixels, printed to 7 decimals.
//
// Tolerance: the reference computes in float, this implementation in double. On these images the
// means agree to 3.1e-6 and every pixel to 1.4e-4. The largest pixel differences sit where the
// colour difference is at float's rounding level (the reference rounds it to 0) and the feature
// difference is large, so FLIP = Δc^(1 - Δf) lifts a tiny Δc. Hence 1e-5 on the mean (3x the worst
// seen, 100x below the smallest difference between two cases' means that matters here) and 2e-4
// on a pixel.
constexpr double kMeanTolerance = 1e-5;
constexpr double kPixelTolerance = 2e-4;

struct ReferencePixel {
  int x, y;
  double value;
};

void expect_reference(const FlipResult& r, double mean, std::initializer_list<ReferencePixel> pixels) {
  EXPECT_NEAR(r.mean, mean, kMeanTolerance);
  for (const ReferencePixel& p : pixels) EXPECT_NEAR(at(r, p.x, p.y), p.value, kPixelTolerance) << p.x << "," << p.y;
}

TEST(Flip, MatchesReferenceImplementation) {
  // A gradient to 2.0 against itself with ±20 % noise, exposure 0, the default 67.02 ppd.
  expect_reference(flip_error(gradient(), scaled_by_noise(gradient(), 0.2), {.exposure = 0}), 0.0604779,
                   {{0, 0, 0.1205029}, {5, 3, 0.0623092}, {16, 12, 0.0209345}, {31, 23, 0.0943280}});
  // A square moved by one pixel, exposure -1, 30 ppd: the edges, and 0 inside and far away.
  expect_reference(
      flip_error(square(0), square(1), {.exposure = -1, .pixels_per_degree = 30}), 0.0736619,
      {{7, 12, 0.7756891}, {8, 12, 0.9511363}, {15, 12, 0.3878521}, {16, 12, 0.9511363}, {12, 12, 0.0}, {2, 2, 0.0}});
  // Red against green beside a common blue, exposure +1.
  expect_reference(
      flip_error(halves(false), halves(true), {.exposure = 1}), 0.5506178,
      {{0, 0, 0.9695368}, {8, 12, 0.9726888}, {15, 12, 0.9782041}, {16, 12, 0.8435283}, {24, 12, 0.0050361}});
  // One bright pixel on grey.
  expect_reference(flip_error(grey(false), grey(true)), 0.0064220,
                   {{10, 7, 0.4242042}, {11, 7, 0.3320403}, {13, 7, 0.0355607}, {20, 7, 0.0}, {0, 0, 0.0}});
  // The 96 x 64 scene with ±35 % noise, exposure +0.5, at 67.02 and at 10 ppd.
  expect_reference(flip_error(scene(), scaled_by_noise(scene(), 0.35), {.exposure = 0.5}), 0.0864936,
                   {{0, 0, 0.3056987}, {29, 25, 0.0227259}, {48, 32, 0.0830963}, {95, 63, 0.1710604}});
  expect_reference(flip_error(scene(), scaled_by_noise(scene(), 0.35), {.exposure = 0.5, .pixels_per_degree = 10}),
                   0.2539593, {{0, 0, 0.5337884}, {29, 25, 0.2528788}, {48, 32, 0.0421579}, {95, 63, 0.2929990}});
}

}  // namespace
}  // namespace vsgl
