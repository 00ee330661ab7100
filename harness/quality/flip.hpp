#pragma once
// FLIP (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild 2020, "FLIP: A
// Difference Evaluator for Alternating Images"): the perceived difference between a reference and
// a test image, per pixel in [0, 1], as seen by a viewer flipping between them at a given number
// of pixels per degree of visual angle. Here the LDR FLIP of each image tone-mapped at one fixed
// exposure (DESIGN.md §11a): linear radiance is scaled by 2^exposure, tone-mapped per channel by
// the ACES filmic fit (aces_filmic below) and clamped to [0, 1]; FLIP is computed on that.
//
// The two pipelines of the paper, in its terms:
// - colour: both images in the linear opponent space YCxCz (XYZ relative to the D65 white), each
//   channel filtered by its contrast sensitivity function as a spatial kernel (achromatic,
//   red-green: one Gaussian; blue-yellow: a sum of two), back to linear RGB clamped to [0, 1],
//   then CIELAB with Hunt-adjusted chroma (a, b times 0.01 L), the HyAB distance |ΔL| +
//   ||Δ(a, b)||, raised to q_c = 0.7 and mapped to [0, 1]: [0, p_c c_max) linearly onto [0, p_t),
//   the rest onto [p_t, 1], c_max the distance of green to blue (p_c = 0.4, p_t = 0.95);
// - features: edges and points of the achromatic channel (relative luminance) detected by the
//   first and second derivatives of a Gaussian of standard deviation 0.5 w ppd pixels (w = 0.082°),
//   Δf = (max(|edge_r - edge_t|, |point_r - point_t|) / sqrt 2)^q_f, q_f = 0.5;
// and their combination, FLIP = Δc^(1 - Δf). Filters cover ±3 standard deviations and read the
// nearest edge pixel beyond the image.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "harness/quality/radiance_image.hpp"

namespace vsgl {

// The paper's default observer: 0.7 m from a 0.7 m wide monitor of 3840 pixels, i.e. 3840 · π /
// 180 pixels per degree.
inline constexpr double kFlipDefaultPixelsPerDegree = 67.02064327658226;

struct FlipSettings {
  double exposure = 0;  // stops: linear radiance is multiplied by 2^exposure before tone mapping
  double pixels_per_degree = kFlipDefaultPixelsPerDegree;
};

struct FlipResult {
  uint32_t width = 0, height = 0;
  std::vector<float> error;  // per pixel, row-major like RadianceImage, each in [0, 1]
  double mean = 0;           // mean of `error` over all pixels
};

// The ACES filmic tone curve as fitted by Narkowicz (2015), x (2.51 x + 0.03) / (x (2.43 x + 0.59)
// + 0.14), of 0.6 x: the fit expects the 0.6 pre-exposure of ACES' reference rendering, so an
// exposure of 0 maps a linear 1 near the reference rendering's output. Per channel; not clamped.
double aces_filmic(double x);

// The image FLIP compares: each pixel's rgb (alpha ignored) times 2^exposure, negative values
// taken as 0, aces_filmic per channel, clamped to [0, 1]; linear RGB, row-major.
std::vector<glm::dvec3> tone_mapped(const RadianceImage& image, double exposure);

// LDR FLIP of `test` against `reference` at settings.exposure. Throws std::invalid_argument for
// images of different sizes, an empty image, a pixel count that disagrees with the size, a
// non-finite pixel, exposure or pixels per degree, or pixels per degree not positive.
FlipResult flip_error(const RadianceImage& reference, const RadianceImage& test, const FlipSettings& settings = {});

}  // namespace vsgl
