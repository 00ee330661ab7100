// Fig. 7's occluded region and its error (DESIGN.md §11a.2, quality/occlusion_run.hpp) on made-up
// images whose answer is known: O holds exactly the lit pixels that lose more than half their
// light, a dim pixel or one that loses half exactly stays out, the size rule counts, and the
// relative RMSE is taken over O alone.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "harness/core/error.hpp"
#include "harness/quality/occlusion_run.hpp"

namespace vsgl {
namespace {

RadianceImage grey(uint32_t w, uint32_t h, float v) {
  RadianceImage img{w, h, std::vector<glm::vec4>(std::size_t{w} * h, glm::vec4(v, v, v, 1.0f))};
  return img;
}

TEST(OccludedRegion, HoldsTheLitPixelsThatLoseMoreThanHalfTheirLight) {
  RadianceImage r0 = grey(4, 2, 1.0f), rv = grey(4, 2, 1.0f);
  rv.pixels[0] = glm::vec4(0.2f, 0.2f, 0.2f, 1.0f);     // loses 80 %: in O
  rv.pixels[1] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);     // loses exactly half: not "more than half"
  rv.pixels[2] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);     // loses all: in O
  r0.pixels[3] = glm::vec4(0.01f, 0.01f, 0.01f, 1.0f);  // dim (below 0.05 of the mean) ...
  rv.pixels[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);     // ... so out, whatever it loses
  r0.pixels[4] = glm::vec4(0.0f);                       // no surface: out, and not counted
  rv.pixels[4] = glm::vec4(0.0f);
  const OccludedRegion o = occluded_region(r0, rv);
  EXPECT_EQ(o.inside, (std::vector<uint8_t>{1, 0, 1, 0, 0, 0, 0, 0}));
  EXPECT_EQ(o.surface_pixels, 7u);
  EXPECT_EQ(o.occluded_pixels, 2u);
  EXPECT_NEAR(o.unshadowed_mean_luminance, (6.0 + 0.01) / 7.0, 1e-6);
  EXPECT_NEAR(o.occluded_light_share, (0.8 + 1.0) / 6.01, 1e-6);
  // Two pixels are fewer than 50: no occluded region.
  EXPECT_FALSE(o.large_enough());
  EXPECT_THROW(occluded_region(r0, grey(2, 2, 1.0f)), InputError);
}

TEST(OccludedRegion, IsLargeEnoughFromFiftyPixelsAndOnePercent) {
  OccludedRegion o;
  o.surface_pixels = 1000;
  o.occluded_pixels = 50;
  EXPECT_TRUE(o.large_enough());
  o.occluded_pixels = 49;
  EXPECT_FALSE(o.large_enough());
  o.surface_pixels = 10000;  // 99 of 10000 is under 1 %
  o.occluded_pixels = 99;
  EXPECT_FALSE(o.large_enough());
  o.occluded_pixels = 100;
  EXPECT_TRUE(o.large_enough());
}

TEST(OccludedRegion, RelativeRmseIsTakenOverTheRegionAlone) {
  const RadianceImage reference = grey(2, 2, 1.0f);
  RadianceImage frame = grey(2, 2, 1.0f);
  frame.pixels[0] = glm::vec4(1.5f, 1.5f, 1.5f, 1.0f);     // in O: off by 0.5 in each channel
  frame.pixels[3] = glm::vec4(10.0f, 10.0f, 10.0f, 1.0f);  // outside O: not counted
  const std::vector<uint8_t> region{1, 1, 0, 0};
  // sqrt(3 * 0.25 / (2 * 3)) = sqrt(0.125)
  EXPECT_NEAR(region_relative_rmse(frame, reference, region), std::sqrt(0.125), 1e-12);
  EXPECT_EQ(region_relative_rmse(reference, reference, region), 0.0);
  EXPECT_TRUE(std::isinf(region_relative_rmse(frame, grey(2, 2, 0.0f), region)));
  EXPECT_THROW(region_relative_rmse(frame, reference, std::vector<uint8_t>{1, 0}), InputError);
}

}  // namespace
}  // namespace vsgl
