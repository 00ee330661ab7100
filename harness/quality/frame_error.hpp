#pragma once
// The image error of one frame against its reference (DESIGN.md §11a.1): a pure CPU function over
// radiance images, so tests can feed it known answers. Over frames, core's summarize.
#include <cstdint>

#include "harness/quality/flip.hpp"
#include "harness/quality/radiance_image.hpp"

namespace vsgl {

// Over the pixels where the reference has a surface; L the frame, R the reference, Y luminance
// (Rec. 709), mean_Y the reference's mean luminance.
struct FrameImageError {
  double rel_mse = 0;          // mean (Y_L - Y_R)^2 / (Y_R^2 + 0.01 mean_Y^2)
  double relative_rmse = 0;    // sqrt(sum |L - R|^2 / sum |R|^2), rgb
  double scale = 0;            // s* = sum L.R / sum L.L: the global factor that brings L closest to R
  double scaled_rmse = 0;      // the relative RMSE of s* L: the error once the bias is taken out
  double flip = 0;             // mean LDR FLIP at the settings' exposure
  double p99_pixel_error = 0;  // 99th percentile of |Y_L - Y_R| / mean_Y
  double max_pixel_error = 0;  // its maximum
};

// Throws InputError for images of different sizes or a black reference. A black frame has scale 0.
FrameImageError frame_image_error(const RadianceImage& frame, const RadianceImage& reference, const FlipSettings& flip);

}  // namespace vsgl
