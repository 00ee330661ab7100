#include "harness/quality/frame_error.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "harness/core/error.hpp"
#include "harness/core/statistics.hpp"
#include "harness/math/vsgl_math.hpp"

namespace vsgl {
namespace {

double lum(glm::vec4 p) { return static_cast<double>(luminance(glm::vec3(p))); }

// relMSE's denominator term, relative to the reference's mean luminance squared (DESIGN.md §11a.1).
constexpr double kRelMseEpsilon = 0.01;

}  // namespace

FrameImageError frame_image_error(const RadianceImage& frame, const RadianceImage& reference,
                                  const FlipSettings& flip) {
  if (frame.width != reference.width || frame.height != reference.height ||
      frame.pixels.size() != reference.pixels.size())
    throw InputError("image error: the frame is " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                     " but the reference is " + std::to_string(reference.width) + "x" +
                     std::to_string(reference.height));
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
    ref_lum += lum(r);
  }
  if (!(rr > 0.0) || !(ref_lum > 0.0)) throw InputError("image error: the reference image is black");
  const double mean_y = ref_lum / static_cast<double>(surface.size());
  FrameImageError e;
  // A black frame fits the reference equally badly at every scale: s* = 0, and its scaled error is 1.
  e.scale = ll > 0.0 ? lr / ll : 0.0;
  double err2 = 0, scaled2 = 0, rel = 0;
  std::vector<double> pixel_error;
  pixel_error.reserve(surface.size());
  for (std::size_t i : surface) {
    const glm::vec4 r = reference.pixels[i], l = frame.pixels[i];
    for (int c = 0; c < 3; ++c) {
      const double lc = l[c], rc = r[c];
      const double d = lc - rc, ds = e.scale * lc - rc;
      err2 += d * d;
      scaled2 += ds * ds;
    }
    const double yr = lum(r), dy = lum(l) - yr;
    rel += dy * dy / (yr * yr + kRelMseEpsilon * mean_y * mean_y);
    pixel_error.push_back(std::abs(dy) / mean_y);
  }
  e.rel_mse = rel / static_cast<double>(surface.size());
  e.relative_rmse = std::sqrt(err2 / rr);
  e.scaled_rmse = std::sqrt(scaled2 / rr);
  std::sort(pixel_error.begin(), pixel_error.end());
  e.p99_pixel_error = quantile_sorted(pixel_error, 0.99);
  e.max_pixel_error = pixel_error.back();
  e.flip = flip_error(reference, frame, flip).mean;
  return e;
}

}  // namespace vsgl
