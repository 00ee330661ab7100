#include "harness/quality/frame_error.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "harness/core/error.hpp"
#include "harness/quality/quality_metrics.hpp"

namespace vsgl {
namespace {

// relMSE's denominator term, relative to the reference's mean luminance squared (DESIGN.md §11a.1).
constexpr double kRelMseEpsilon = 0.01;

}  // namespace

FrameImageError frame_image_error(const RadianceImage& frame, const RadianceImage& reference,
                                  const FlipSettings& flip) {
  if (frame.pixels.size() != reference.pixels.size())
    throw InputError("image error: the frame has " + std::to_string(frame.pixels.size()) +
                     " pixels but the reference " + std::to_string(reference.pixels.size()));
  // The relative RMSE and the p99 pixel error are image_error's, defined once; it also refuses
  // images of different sizes and a black reference.
  const ImageError base = image_error(frame, reference);
  FrameImageError e;
  e.relative_rmse = base.relative_rmse;
  e.p99_pixel_error = base.p99_pixel_error;
  double lr = 0, ll = 0, rr = 0, ref_lum = 0;
  std::vector<std::size_t> surface;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    const glm::vec4 r = reference.pixels[i], l = frame.pixels[i];
    if (!(r.a > 0.0f)) continue;
    surface.push_back(i);
    for (int c = 0; c < 3; ++c) {
      const double lc = l[c], rc = r[c];
      lr += lc * rc;
      ll += lc * lc;
      rr += rc * rc;
    }
    ref_lum += pixel_luminance(r);
  }
  const double mean_y = ref_lum / static_cast<double>(surface.size());
  // A black frame fits the reference equally badly at every scale: s* = 0, and its scaled error is 1.
  e.scale = ll > 0.0 ? lr / ll : 0.0;
  double scaled2 = 0, rel = 0;
  for (std::size_t i : surface) {
    const glm::vec4 r = reference.pixels[i], l = frame.pixels[i];
    for (int c = 0; c < 3; ++c) {
      const double ds = e.scale * static_cast<double>(l[c]) - static_cast<double>(r[c]);
      scaled2 += ds * ds;
    }
    const double yr = pixel_luminance(r), dy = pixel_luminance(l) - yr;
    rel += dy * dy / (yr * yr + kRelMseEpsilon * mean_y * mean_y);
    e.max_pixel_error = std::max(e.max_pixel_error, std::abs(dy) / mean_y);
  }
  e.rel_mse = rel / static_cast<double>(surface.size());
  e.scaled_rmse = std::sqrt(scaled2 / rr);
  e.flip = flip_error(reference, frame, flip).mean;
  return e;
}

}  // namespace vsgl
