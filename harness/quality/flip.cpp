#include "harness/quality/flip.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace vsgl {

namespace {

// ---- Colour spaces ----------------------------------------------------------------------------

// The white of every space here: CIE D65 at (0.31271, 0.32902) (CIE 15), Y = 1. IEC 61966-2-1
// rounds it to (0.3127, 0.3290); one white for the RGB matrix and for CIELAB and YCxCz keeps RGB
// (1, 1, 1) exactly the reference white, so a grey has no chroma in either space.
constexpr double kWhiteX = 0.31271, kWhiteY = 0.32902;

glm::dvec3 xyz_of_chromaticity(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

// Linear sRGB to XYZ, derived from the sRGB primaries (IEC 61966-2-1: R (0.64, 0.33), G (0.30,
// 0.60), B (0.15, 0.06)) and the white rather than typed in: the columns are the primaries' XYZ,
// scaled so that RGB (1, 1, 1) is the white.
glm::dmat3 xyz_from_primaries() {
  const glm::dmat3 primaries(xyz_of_chromaticity(0.64, 0.33), xyz_of_chromaticity(0.30, 0.60),
                             xyz_of_chromaticity(0.15, 0.06));  // columns
  const glm::dvec3 scale = glm::inverse(primaries) * xyz_of_chromaticity(kWhiteX, kWhiteY);
  return glm::dmat3(primaries[0] * scale.x, primaries[1] * scale.y, primaries[2] * scale.z);
}

struct ColourSpaces {
  glm::dmat3 rgb_to_xyz = xyz_from_primaries();
  glm::dmat3 xyz_to_rgb = glm::inverse(rgb_to_xyz);
  glm::dvec3 white = xyz_of_chromaticity(kWhiteX, kWhiteY);
};

const ColourSpaces& colour_spaces() {
  static const ColourSpaces spaces;
  return spaces;
}

// YCxCz, the linear opponent space of the colour pipeline: Y = 116 Y/Yn - 16, Cx = 500 (X/Xn -
// Y/Yn), Cz = 200 (Y/Yn - Z/Zn): CIELAB's formulas without the cube root.
glm::dvec3 ycxcz_from_rgb(const glm::dvec3& rgb) {
  const ColourSpaces& cs = colour_spaces();
  const glm::dvec3 t = (cs.rgb_to_xyz * rgb) / cs.white;
  return {116.0 * t.y - 16.0, 500.0 * (t.x - t.y), 200.0 * (t.y - t.z)};
}

glm::dvec3 rgb_from_ycxcz(const glm::dvec3& c) {
  const ColourSpaces& cs = colour_spaces();
  const double y = (c.x + 16.0) / 116.0;
  const glm::dvec3 t(y + c.y / 500.0, y, y - c.z / 200.0);
  return cs.xyz_to_rgb * (t * cs.white);
}

// CIELAB (CIE 15) of linear RGB, chroma then Hunt-adjusted: a and b times 0.01 L, so that a
// colour difference weighs less in the dark, as the eye sees it.
glm::dvec3 hunt_lab_from_rgb(const glm::dvec3& rgb) {
  const ColourSpaces& cs = colour_spaces();
  const glm::dvec3 t = (cs.rgb_to_xyz * rgb) / cs.white;
  constexpr double delta = 6.0 / 29.0;
  const auto f = [](double v) {
    return v > delta * delta * delta ? std::cbrt(v) : v / (3.0 * delta * delta) + 4.0 / 29.0;
  };
  const double fx = f(t.x), fy = f(t.y), fz = f(t.z);
  const double l = 116.0 * fy - 16.0;
  return {l, 0.01 * l * 500.0 * (fx - fy), 0.01 * l * 200.0 * (fy - fz)};
}

// HyAB: city-block in lightness, Euclidean in chroma; better than ΔE for large differences.
double hyab(const glm::dvec3& p, const glm::dvec3& q) { return std::abs(p.x - q.x) + std::hypot(p.y - q.y, p.z - q.z); }

// ---- The paper's constants ----------------------------------------------------------------------

constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95;  // colour: exponent, knee, value at the knee
constexpr double kW = 0.082, kQf = 0.5;             // features: width in degrees, exponent

// The contrast sensitivity functions as spatial kernels of distance x in degrees, per channel of
// YCxCz: a1 sqrt(π/b1) exp(-π² x²/b1) + a2 sqrt(π/b2) exp(-π² x²/b2).
struct Csf {
  double a1, b1, a2, b2;
};
constexpr Csf kCsfAchromatic{1.0, 0.0047, 0.0, 1e-5};
constexpr Csf kCsfRedGreen{1.0, 0.0053, 0.0, 1e-5};
constexpr Csf kCsfBlueYellow{34.1, 0.04, 13.5, 0.025};

// ---- Separable filtering ------------------------------------------------------------------------

using Kernel = std::vector<double>;  // 2 r + 1 taps, centre at r

struct Plane {
  int width = 0, height = 0;
  std::vector<double> v;
  double at(int x, int y) const { return v[static_cast<std::size_t>(y) * width + x]; }
};

// Filters rows with `along_x`, then columns with `along_y`; a tap beyond the image reads the
// nearest edge pixel.
Plane filter_separable(const Plane& in, const Kernel& along_x, const Kernel& along_y) {
  const int w = in.width, h = in.height;
  Plane rows{w, h, std::vector<double>(in.v.size())};
  const int rx = static_cast<int>(along_x.size() / 2), ry = static_cast<int>(along_y.size() / 2);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int i = -rx; i <= rx; ++i) s += along_x[i + rx] * in.at(std::clamp(x + i, 0, w - 1), y);
      rows.v[static_cast<std::size_t>(y) * w + x] = s;
    }
  Plane out{w, h, std::vector<double>(in.v.size())};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int i = -ry; i <= ry; ++i) s += along_y[i + ry] * rows.at(x, std::clamp(y + i, 0, h - 1));
      out.v[static_cast<std::size_t>(y) * w + x] = s;
    }
  return out;
}

// One Gaussian term of a CSF kernel as a 1D factor: g(x) g(y) = a sqrt(π/b) exp(-π² (x² + y²)/b),
// the 2D kernel at distance sqrt(x² + y²), so g = sqrt(a sqrt(π/b)) exp(-π² x²/b).
Kernel csf_factor(double a, double b, int radius, double ppd) {
  const double pi = std::numbers::pi;
  Kernel k(2 * radius + 1);
  for (int i = -radius; i <= radius; ++i) {
    const double x = i / ppd;  // degrees
    k[i + radius] = std::sqrt(a * std::sqrt(pi / b)) * std::exp(-pi * pi * x * x / b);
  }
  return k;
}

double sum_of(const Kernel& k) {
  double s = 0;
  for (double v : k) s += v;
  return s;
}

// A channel's CSF kernel as one or two separable terms, scaled so that the whole 2D kernel sums
// to 1 (its taps sum to the product of the factors' sums, so by S1² + S2²).
std::vector<Kernel> csf_kernel(const Csf& csf, int radius, double ppd) {
  std::vector<Kernel> terms{csf_factor(csf.a1, csf.b1, radius, ppd)};
  if (csf.a2 != 0) terms.push_back(csf_factor(csf.a2, csf.b2, radius, ppd));
  double total = 0;
  for (const Kernel& k : terms) total += sum_of(k) * sum_of(k);
  const double norm = 1.0 / std::sqrt(total);
  for (Kernel& k : terms)
    for (double& v : k) v *= norm;
  return terms;
}

Plane filter_csf(const Plane& in, const std::vector<Kernel>& terms) {
  Plane out = filter_separable(in, terms[0], terms[0]);
  for (std::size_t t = 1; t < terms.size(); ++t) {
    const Plane more = filter_separable(in, terms[t], terms[t]);
    for (std::size_t i = 0; i < out.v.size(); ++i) out.v[i] += more.v[i];
  }
  return out;
}

// The feature detectors' 1D factors: the Gaussian of standard deviation sigma (pixels), summing
// to 1, and its first and second derivatives, whose positive taps sum to 1 and negative to -1 (so
// a unit step or spike in a [0, 1] image gives a response of at most 1).
struct FeatureKernels {
  Kernel gaussian, first, second;
};

FeatureKernels feature_kernels(double ppd) {
  const double sigma = 0.5 * kW * ppd;
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  FeatureKernels k{Kernel(2 * radius + 1), Kernel(2 * radius + 1), Kernel(2 * radius + 1)};
  for (int i = -radius; i <= radius; ++i) {
    const double x = i;
    const double g = std::exp(-x * x / (2.0 * sigma * sigma));
    k.gaussian[i + radius] = g;
    k.first[i + radius] = -x * g;
    k.second[i + radius] = (x * x / (sigma * sigma) - 1.0) * g;
  }
  const double gs = sum_of(k.gaussian);
  for (double& v : k.gaussian) v /= gs;
  for (Kernel* d : {&k.first, &k.second}) {
    double positive = 0, negative = 0;
    for (double v : *d) (v > 0 ? positive : negative) += v;
    for (double& v : *d) v /= v > 0 ? positive : -negative;
  }
  return k;
}

// Per pixel, the magnitudes of the edge (first derivative) and point (second derivative)
// responses of the achromatic channel.
struct Features {
  Plane edge, point;
};

Features detect_features(const Plane& luminance, const FeatureKernels& k) {
  const Plane dx = filter_separable(luminance, k.first, k.gaussian);
  const Plane dy = filter_separable(luminance, k.gaussian, k.first);
  const Plane ddx = filter_separable(luminance, k.second, k.gaussian);
  const Plane ddy = filter_separable(luminance, k.gaussian, k.second);
  Features f{dx, ddx};
  for (std::size_t i = 0; i < dx.v.size(); ++i) {
    f.edge.v[i] = std::hypot(dx.v[i], dy.v[i]);
    f.point.v[i] = std::hypot(ddx.v[i], ddy.v[i]);
  }
  return f;
}

void check_image(const RadianceImage& image, const char* which) {
  if (image.width == 0 || image.height == 0)
    throw std::invalid_argument(std::string("FLIP: the ") + which + " image is empty");
  if (image.pixels.size() != static_cast<std::size_t>(image.width) * image.height)
    throw std::invalid_argument(std::string("FLIP: the ") + which + " image's pixel count disagrees with its size");
  for (const glm::vec4& p : image.pixels)
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b))
      throw std::invalid_argument(std::string("FLIP: the ") + which + " image has a pixel that is not finite");
}

}  // namespace

double aces_filmic(double x) {
  const double v = 0.6 * x;
  return v * (2.51 * v + 0.03) / (v * (2.43 * v + 0.59) + 0.14);
}

std::vector<glm::dvec3> tone_mapped(const RadianceImage& image, double exposure) {
  const double scale = std::exp2(exposure);
  std::vector<glm::dvec3> out(image.pixels.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int c = 0; c < 3; ++c)  // a negative value (no radiance is) would map bright: taken as 0
      out[i][c] = std::clamp(aces_filmic(std::max(0.0, scale * static_cast<double>(image.pixels[i][c]))), 0.0, 1.0);
  return out;
}

FlipResult flip_error(const RadianceImage& reference, const RadianceImage& test, const FlipSettings& settings) {
  check_image(reference, "reference");
  check_image(test, "test");
  if (reference.width != test.width || reference.height != test.height)
    throw std::invalid_argument("FLIP: the reference is " + std::to_string(reference.width) + "x" +
                                std::to_string(reference.height) + ", the test " + std::to_string(test.width) + "x" +
                                std::to_string(test.height));
  if (!std::isfinite(settings.exposure)) throw std::invalid_argument("FLIP: the exposure is not finite");
  if (!(settings.pixels_per_degree > 0) || !std::isfinite(settings.pixels_per_degree))
    throw std::invalid_argument("FLIP: pixels per degree must be finite and positive");
  const double ppd = settings.pixels_per_degree;
  const int w = static_cast<int>(reference.width), h = static_cast<int>(reference.height);
  const std::size_t n = reference.pixels.size();

  // Both images as YCxCz planes, and their relative luminance (Y/Yn, in [0, 1] after the clamp)
  // for the feature pipeline.
  struct Planes {
    Plane channel[3];
    Plane luminance;
  };
  const auto planes_of = [&](const RadianceImage& image) {
    const std::vector<glm::dvec3> ldr = tone_mapped(image, settings.exposure);
    Planes p;
    for (Plane* q : {&p.channel[0], &p.channel[1], &p.channel[2], &p.luminance})
      *q = Plane{w, h, std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3 c = ycxcz_from_rgb(ldr[i]);
      for (int k = 0; k < 3; ++k) p.channel[k].v[i] = c[k];
      p.luminance.v[i] = (c.x + 16.0) / 116.0;
    }
    return p;
  };
  const Planes ref = planes_of(reference), tst = planes_of(test);

  // Colour pipeline. One radius for all three channels: 3 standard deviations of the widest
  // Gaussian (exp(-π² x²/b) has variance b / (2π²)), in pixels.
  const double widest = std::max({kCsfAchromatic.b1, kCsfRedGreen.b1, kCsfBlueYellow.b1, kCsfBlueYellow.b2});
  const int radius =
      static_cast<int>(std::ceil(3.0 * std::sqrt(widest / (2.0 * std::numbers::pi * std::numbers::pi)) * ppd));
  const std::vector<Kernel> csf[3] = {csf_kernel(kCsfAchromatic, radius, ppd), csf_kernel(kCsfRedGreen, radius, ppd),
                                      csf_kernel(kCsfBlueYellow, radius, ppd)};
  Plane ref_filtered[3], tst_filtered[3];
  for (int k = 0; k < 3; ++k) {
    ref_filtered[k] = filter_csf(ref.channel[k], csf[k]);
    tst_filtered[k] = filter_csf(tst.channel[k], csf[k]);
  }
  const auto lab_at = [](const Plane(&f)[3], std::size_t i) {
    const glm::dvec3 rgb = glm::clamp(rgb_from_ycxcz({f[0].v[i], f[1].v[i], f[2].v[i]}), 0.0, 1.0);
    return hunt_lab_from_rgb(rgb);
  };
  const double cmax = std::pow(hyab(hunt_lab_from_rgb({0, 1, 0}), hunt_lab_from_rgb({0, 0, 1})), kQc);
  const double knee = kPc * cmax;

  // Feature pipeline.
  const FeatureKernels fk = feature_kernels(ppd);
  const Features ref_features = detect_features(ref.luminance, fk), tst_features = detect_features(tst.luminance, fk);

  FlipResult result;
  result.width = reference.width;
  result.height = reference.height;
  result.error.resize(n);
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double colour = std::pow(hyab(lab_at(ref_filtered, i), lab_at(tst_filtered, i)), kQc);
    colour = colour < knee ? colour * kPt / knee : kPt + (colour - knee) / (cmax - knee) * (1.0 - kPt);
    const double edge = std::abs(ref_features.edge.v[i] - tst_features.edge.v[i]);
    const double point = std::abs(ref_features.point.v[i] - tst_features.point.v[i]);
    const double feature = std::pow(std::max(edge, point) / std::numbers::sqrt2, kQf);
    // colour can exceed 1 only by rounding beyond c_max; feature stays in [0, 1] since each
    // response of a [0, 1] image is at most sqrt 2. Clamped so the map is a valid [0, 1] error.
    const double e = std::clamp(std::pow(std::min(colour, 1.0), 1.0 - std::min(feature, 1.0)), 0.0, 1.0);
    result.error[i] = static_cast<float>(e);
    sum += e;
  }
  result.mean = sum / static_cast<double>(n);
  return result;
}

}  // namespace vsgl
