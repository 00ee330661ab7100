#include "harness/quality/quality_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "harness/core/error.hpp"
#include "harness/core/statistics.hpp"

namespace vsgl {
double pixel_luminance(glm::vec4 p) { return static_cast<double>(luminance(glm::vec3(p))); }

std::vector<uint32_t> footprint_counts(const std::vector<VsglRecord>& kernels, const VirtualSquare& square) {
  const int64_t w = square.width, h = square.height;
  // 2D difference array: +1 at a footprint's first texel, -1 past its ends; prefix sums give the
  // count per texel in O(N + W H) however large the footprints are.
  std::vector<int32_t> diff(static_cast<std::size_t>((w + 1) * (h + 1)), 0);
  const auto at = [&](int64_t x, int64_t y) -> int32_t& { return diff[static_cast<std::size_t>(y * (w + 1) + x)]; };
  const double S = static_cast<double>(square.size);
  for (const VsglRecord& k : kernels) {
    const double level = static_cast<double>(k.level());
    if (!(level >= 0.0)) throw InputError("kernel coverage: a VSGL has no FIS level (k-means records carry -1)");
    const double half = 0.5 * std::exp2(level);
    const double cx = static_cast<double>(k.center().x) * S, cy = static_cast<double>(k.center().y) * S;
    // Texel t's centre t + 0.5 in [c - h, c + h)  <=>  t in [ceil(c - h - 0.5), ceil(c + h - 0.5)).
    const int64_t x0 = std::clamp<int64_t>(static_cast<int64_t>(std::ceil(cx - half - 0.5)), 0, w);
    const int64_t x1 = std::clamp<int64_t>(static_cast<int64_t>(std::ceil(cx + half - 0.5)), 0, w);
    const int64_t y0 = std::clamp<int64_t>(static_cast<int64_t>(std::ceil(cy - half - 0.5)), 0, h);
    const int64_t y1 = std::clamp<int64_t>(static_cast<int64_t>(std::ceil(cy + half - 0.5)), 0, h);
    if (x0 >= x1 || y0 >= y1) continue;
    ++at(x0, y0);
    --at(x1, y0);
    --at(x0, y1);
    ++at(x1, y1);
  }
  std::vector<uint32_t> counts(static_cast<std::size_t>(w * h));
  std::vector<int64_t> column(static_cast<std::size_t>(w + 1), 0);
  for (int64_t y = 0; y < h; ++y) {
    int64_t run = 0;
    for (int64_t x = 0; x < w; ++x) {
      column[static_cast<std::size_t>(x)] += at(x, y);
      run += column[static_cast<std::size_t>(x)];
      counts[static_cast<std::size_t>(y * w + x)] = static_cast<uint32_t>(run);
    }
  }
  return counts;
}

KernelCoverage kernel_coverage(const std::vector<VsglRecord>& kernels, const MipPyramid& pdf_pyramid, float K) {
  if (kernels.empty()) throw InputError("kernel coverage: no kernels");
  const VirtualSquare& sq = pdf_pyramid.square;
  const std::vector<uint32_t> counts = footprint_counts(kernels, sq);
  KernelCoverage c;
  double total = 0, gap = 0, overlap = 0;
  for (uint32_t y = 0; y < sq.height; ++y)
    for (uint32_t x = 0; x < sq.width; ++x) {
      const uint32_t n = counts[std::size_t{y} * sq.width + x];
      c.covered_centres += n;
      const double q = static_cast<double>(pdf_pyramid.at(0, static_cast<int32_t>(x), static_cast<int32_t>(y)).w);
      if (!(q > 0.0)) continue;
      ++c.texels_with_pdf;
      total += q;
      if (n == 0) {
        gap += q;
        ++c.gap_texels;
      } else if (n >= 2) {
        overlap += q;
        ++c.overlap_texels;
      }
    }
  if (!(total > 0.0)) throw InputError("kernel coverage: the PDF is zero everywhere");
  c.gap = gap / total;
  c.overlap = overlap / total;
  const double n_over_k = static_cast<double>(kernels.size()) / static_cast<double>(K);
  for (const VsglRecord& k : kernels)
    c.mass_ratio.push_back(static_cast<double>(modified_kernel_mass(pdf_pyramid, k.center(), k.level())) * n_over_k);
  c.mass = summarize(c.mass_ratio);
  return c;
}

std::vector<double> trilinear_footprint_sum(const std::vector<VsglRecord>& kernels, const std::vector<double>& weights,
                                            const VirtualSquare& square) {
  if (weights.size() != kernels.size()) throw std::invalid_argument("trilinear_footprint_sum: one weight per kernel");
  const int64_t w = square.width, h = square.height;
  // The same difference-array trick as footprint_counts, with real weights: each kernel adds up to
  // 8 rectangles (4 bilinear taps on 2 levels), each a level-l texel's block of level-0 texels.
  std::vector<double> diff(static_cast<std::size_t>((w + 1) * (h + 1)), 0.0);
  const auto at = [&](int64_t x, int64_t y) -> double& { return diff[static_cast<std::size_t>(y * (w + 1) + x)]; };
  const auto add_tap = [&](uint32_t level, int64_t tx, int64_t ty, double weight) {
    if (weight == 0.0 || tx < 0 || ty < 0 || tx >= square.level_width(level) || ty >= square.level_height(level)) return;
    const int64_t side = int64_t{1} << level;
    const int64_t x0 = tx * side, y0 = ty * side;
    const int64_t x1 = std::min(x0 + side, w), y1 = std::min(y0 + side, h);
    at(x0, y0) += weight;
    at(x1, y0) -= weight;
    at(x0, y1) -= weight;
    at(x1, y1) += weight;
  };
  // Bilinear taps at `level` exactly as bilinear() places them; each tap's level-0 children get
  // weight * (its bilinear weight) / 4^level.
  const auto add_bilinear = [&](glm::vec2 x, uint32_t level, double weight) {
    const double sk = static_cast<double>(square.size >> level);
    const double ux = static_cast<double>(x.x) * sk - 0.5, uy = static_cast<double>(x.y) * sk - 0.5;
    const double ix = std::floor(ux), iy = std::floor(uy);
    const double fx = ux - ix, fy = uy - iy;
    const double per_child = weight / std::exp2(2.0 * level);
    const auto tx = static_cast<int64_t>(ix), ty = static_cast<int64_t>(iy);
    add_tap(level, tx, ty, per_child * (1.0 - fx) * (1.0 - fy));
    add_tap(level, tx + 1, ty, per_child * fx * (1.0 - fy));
    add_tap(level, tx, ty + 1, per_child * (1.0 - fx) * fy);
    add_tap(level, tx + 1, ty + 1, per_child * fx * fy);
  };
  const double top = static_cast<double>(square.levels);
  for (std::size_t i = 0; i < kernels.size(); ++i) {
    const double raw = static_cast<double>(kernels[i].level());
    if (!(raw >= 0.0)) throw InputError("kernel coverage: a VSGL has no FIS level (k-means records carry -1)");
    const double l = std::min(raw, top);
    const double l0 = std::floor(l);
    const auto k0 = static_cast<uint32_t>(l0);
    const uint32_t k1 = std::min(k0 + 1, square.levels);
    const double t = l - l0;
    add_bilinear(kernels[i].center(), k0, weights[i] * (1.0 - t));
    add_bilinear(kernels[i].center(), k1, weights[i] * t);
  }
  std::vector<double> sums(static_cast<std::size_t>(w * h));
  std::vector<double> column(static_cast<std::size_t>(w + 1), 0.0);
  for (int64_t y = 0; y < h; ++y) {
    double run = 0;
    for (int64_t x = 0; x < w; ++x) {
      column[static_cast<std::size_t>(x)] += at(x, y);
      run += column[static_cast<std::size_t>(x)];
      sums[static_cast<std::size_t>(y * w + x)] = run;
    }
  }
  return sums;
}

std::vector<double> eq3_footprint_counts(const std::vector<VsglRecord>& kernels, const VirtualSquare& square) {
  // k_i(t) = 4^l_i w_i(t): each kernel weighted by a(l) M, its share of the square in texels.
  std::vector<double> area(kernels.size());
  const double top = static_cast<double>(square.levels);
  for (std::size_t i = 0; i < kernels.size(); ++i)
    area[i] = std::exp2(2.0 * std::min(static_cast<double>(kernels[i].level()), top));
  std::vector<double> counts = trilinear_footprint_sum(kernels, area, square);
  // Prefix sums of +/- weights leave rounding residue (~1e-13) on texels no kernel reaches; those
  // are exact zeros in the definition, and a gap must read as a full gap.
  for (double& n : counts)
    if (std::abs(n) < 1e-9) n = 0.0;
  return counts;
}

CoverageCounts coverage_counts(const std::vector<double>& n, const MipPyramid& pdf_pyramid) {
  const VirtualSquare& sq = pdf_pyramid.square;
  if (n.size() != std::size_t{sq.width} * sq.height)
    throw std::invalid_argument("coverage_counts: one count per in-bounds texel expected");
  double total = 0, gap = 0, surplus = 0, mean = 0;
  for (uint32_t y = 0; y < sq.height; ++y)
    for (uint32_t x = 0; x < sq.width; ++x) {
      const double q = static_cast<double>(pdf_pyramid.at(0, static_cast<int32_t>(x), static_cast<int32_t>(y)).w);
      if (!(q > 0.0)) continue;
      const double c = n[std::size_t{y} * sq.width + x];
      total += q;
      gap += q * std::max(1.0 - c, 0.0);
      surplus += q * std::max(c - 1.0, 0.0);
      mean += q * c;
    }
  if (!(total > 0.0)) throw InputError("kernel coverage: the PDF is zero everywhere");
  CoverageCounts out;
  out.gap = gap / total;
  out.surplus = surplus / total;
  out.count_error = (gap + surplus) / total;
  out.mean_count = mean / total;
  return out;
}

FootprintCoverage footprint_coverage(const std::vector<VsglRecord>& kernels, const MipPyramid& pdf_pyramid, float K) {
  FootprintCoverage f;
  f.coverage = kernel_coverage(kernels, pdf_pyramid, K);
  const std::vector<uint32_t> box = footprint_counts(kernels, pdf_pyramid.square);
  f.box = coverage_counts(std::vector<double>(box.begin(), box.end()), pdf_pyramid);
  f.eq3 = coverage_counts(eq3_footprint_counts(kernels, pdf_pyramid.square), pdf_pyramid);
  return f;
}

ViewImage uniform_pdf_view(const ViewImage& view) {
  ViewImage out = view;
  std::vector<float>& pdf = out.planes[kPdf];
  if (pdf.size() != view.texels() || view.planes[kValid].size() != view.texels())
    throw InputError(std::string(view_label(view.kind)) + ": the view has no PDF to replace");
  // The generators weigh a texel by q only where it is valid (texel_moments): the same support.
  for (std::size_t i = 0; i < pdf.size(); ++i) pdf[i] = view.planes[kValid][i] != 0.0f && pdf[i] > 0.0f ? 1.0f : 0.0f;
  return out;
}

namespace {
CoverageCounts minus(const CoverageCounts& a, const CoverageCounts& b) {
  return CoverageCounts{a.gap - b.gap, a.surplus - b.surplus, a.count_error - b.count_error, a.mean_count - b.mean_count};
}
}  // namespace

CoverageExcess coverage_excess(const FootprintCoverage& generator, const FootprintCoverage& floor) {
  CoverageExcess e;
  e.box = minus(generator.box, floor.box);
  e.eq3 = minus(generator.eq3, floor.eq3);
  e.box_gap = generator.coverage.gap - floor.coverage.gap;
  e.box_overlap = generator.coverage.overlap - floor.coverage.overlap;
  return e;
}

PdfFrequency pdf_frequency(const MipPyramid& pdf) {
  const VirtualSquare& sq = pdf.square;
  const double mean = static_cast<double>(pdf.top().w);  // q_bar_L
  if (!(mean > 0.0) || !std::isfinite(mean)) throw InputError("PDF frequency: the PDF is zero everywhere");
  const double M = static_cast<double>(sq.square_texels());
  PdfFrequency f;
  double square_sum = 0;
  for (uint32_t y = 0; y < sq.height; ++y)
    for (uint32_t x = 0; x < sq.width; ++x) {
      const double p = static_cast<double>(pdf.at(0, static_cast<int32_t>(x), static_cast<int32_t>(y)).w) / mean;
      square_sum += p * p;
    }
  f.mean_square = square_sum / M;
  // Level l's detail, parent by parent: a level-(l+1) texel's 4 children (those outside level l's
  // extent read zero, as the pyramid defines them) each stand for 4^l level-0 texels.
  for (uint32_t l = 0; l < sq.levels; ++l) {
    double e = 0;
    const double children_texels = std::exp2(2.0 * l);
    for (uint32_t py = 0; py < sq.level_height(l + 1); ++py)
      for (uint32_t px = 0; px < sq.level_width(l + 1); ++px) {
        const double parent = static_cast<double>(pdf.at(l + 1, static_cast<int32_t>(px), static_cast<int32_t>(py)).w);
        for (uint32_t c = 0; c < 4; ++c) {
          const double child =
              static_cast<double>(pdf.at(l, static_cast<int32_t>(2 * px + (c & 1)), static_cast<int32_t>(2 * py + (c >> 1))).w);
          e += children_texels * (child - parent) * (child - parent);
        }
      }
    f.detail_energy.push_back(e / (M * mean * mean));
  }
  double cumulative = 0;
  for (double e : f.detail_energy) {
    cumulative += e;
    f.relative_variance = cumulative;
    f.fine_share.push_back(cumulative / f.mean_square);
  }
  return f;
}

float scalar_power(const VsglRecord& v) { return v.power().r + v.power().g + v.power().b; }

double total_flux(const std::vector<glm::vec4>& m0) {
  double sum = 0;
  for (const glm::vec4& t : m0) sum += static_cast<double>(t.r) + static_cast<double>(t.g) + static_cast<double>(t.b);
  return sum;
}

PowerMetrics power_metrics(const std::vector<VsglRecord>& vsgls, double flux) {
  if (vsgls.empty()) throw InputError("power metrics: no VSGLs");
  if (!(flux > 0.0)) throw InputError("power metrics: the view's total flux is not positive");
  PowerMetrics m;
  std::vector<double> powers;
  for (const VsglRecord& v : vsgls) powers.push_back(static_cast<double>(scalar_power(v)));
  for (double p : powers) m.total_vsgl_power += p;
  if (!(m.total_vsgl_power > 0.0)) throw InputError("power metrics: the VSGLs carry no power");
  m.total_flux = flux;
  m.power_ratio = m.total_vsgl_power / flux;
  const double mean = m.total_vsgl_power / static_cast<double>(vsgls.size());
  std::sort(powers.begin(), powers.end());
  m.max_over_mean = powers.back() / mean;
  m.p99_over_mean = quantile_sorted(powers, 0.99) / mean;
  return m;
}

double mean_surface_luminance(const RadianceImage& image) {
  double sum = 0;
  std::size_t count = 0;
  for (const glm::vec4& p : image.pixels)
    if (p.a > 0.0f) {
      sum += pixel_luminance(p);
      ++count;
    }
  return count == 0 ? 0.0 : sum / static_cast<double>(count);
}

ImageError image_error(const RadianceImage& image, const RadianceImage& reference) {
  if (image.width != reference.width || image.height != reference.height)
    throw InputError("image error: the image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                     " but the reference is " + std::to_string(reference.width) + "x" +
                     std::to_string(reference.height));
  double err2 = 0, ref2 = 0, ref_lum = 0;
  std::vector<double> abs_lum;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    const glm::vec4 r = reference.pixels[i], p = image.pixels[i];
    if (!(r.a > 0.0f)) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = static_cast<double>(p[c]) - static_cast<double>(r[c]);
      err2 += d * d;
      ref2 += static_cast<double>(r[c]) * static_cast<double>(r[c]);
    }
    ref_lum += pixel_luminance(r);
    abs_lum.push_back(std::abs(pixel_luminance(p) - pixel_luminance(r)));
  }
  if (!(ref2 > 0.0) || !(ref_lum > 0.0)) throw InputError("image error: the reference image is black");
  ImageError e;
  e.relative_rmse = std::sqrt(err2 / ref2);
  std::sort(abs_lum.begin(), abs_lum.end());
  e.p99_pixel_error = quantile_sorted(abs_lum, 0.99) / (ref_lum / static_cast<double>(abs_lum.size()));
  return e;
}

void FlickerAccumulator::check_size(const RadianceImage& image) {
  if (frames_ == 0) {
    width_ = image.width;
    height_ = image.height;
    const std::size_t n = image.pixels.size();
    first_.assign(n, 0.0);
    err_first_.assign(n, 0.0);
    sum_.assign(n, 0.0);
    sum_sq_.assign(n, 0.0);
    err_sum_.assign(n, 0.0);
    err_sum_sq_.assign(n, 0.0);
    ref_sum_.assign(n, 0.0);
    surface_.assign(n, 1);
  } else if (image.width != width_ || image.height != height_) {
    throw InputError("flicker: frame " + std::to_string(frames_) + " is " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + ", the first frame was " + std::to_string(width_) + "x" +
                     std::to_string(height_));
  }
}

void FlickerAccumulator::add_frame(const RadianceImage& image, double total_power) {
  check_size(image);
  std::vector<float> lum(image.pixels.size());
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (!(image.pixels[i].a > 0.0f)) surface_[i] = 0;
    const double y = pixel_luminance(image.pixels[i]);
    if (frames_ == 0) first_[i] = y;
    // Shifted by the first frame: identical frames give exactly zero deviation (and less rounding).
    const double d = y - first_[i];
    sum_[i] += d;
    sum_sq_[i] += d * d;
    lum[i] = static_cast<float>(y);
  }
  luminance_.push_back(std::move(lum));
  powers_.push_back(total_power);
  ++frames_;
}

void FlickerAccumulator::add_frame(const RadianceImage& image, double total_power, const RadianceImage& reference) {
  if (reference.width != image.width || reference.height != image.height)
    throw InputError("flicker: the reference frame's size differs from the frame's");
  if (reference_frames_ != frames_) throw InputError("flicker: every frame needs a reference, or none");
  add_frame(image, total_power);
  std::vector<float> err(image.pixels.size());
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (!(reference.pixels[i].a > 0.0f)) surface_[i] = 0;
    const double r = pixel_luminance(reference.pixels[i]);
    const double e0 = pixel_luminance(image.pixels[i]) - r;
    err[i] = static_cast<float>(e0);
    if (reference_frames_ == 0) err_first_[i] = e0;
    const double e = e0 - err_first_[i];
    err_sum_[i] += e;
    err_sum_sq_[i] += e * e;
    ref_sum_[i] += r;
  }
  error_.push_back(std::move(err));
  ++reference_frames_;
}

namespace {

// delta_f = sum_p |v_f(p) - mean_t v_t(p)| / denominator over the surface pixels.
std::vector<double> deviations_about_mean(const std::vector<std::vector<float>>& frames,
                                          const std::vector<uint8_t>& surface, double denominator) {
  const std::size_t n = surface.size();
  std::vector<double> mean(n, 0.0);
  for (const auto& f : frames)
    for (std::size_t i = 0; i < n; ++i) mean[i] += static_cast<double>(f[i]);
  for (double& m : mean) m /= static_cast<double>(frames.size());
  std::vector<double> out;
  for (const auto& f : frames) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (surface[i]) sum += std::abs(static_cast<double>(f[i]) - mean[i]);
    out.push_back(sum / denominator);
  }
  return out;
}

}  // namespace

std::vector<double> FlickerAccumulator::frame_deviations() const {
  if (frames_ < 2) throw InputError("flicker: needs at least 2 frames");
  double den = 0;
  for (std::size_t i = 0; i < sum_.size(); ++i)
    if (surface_[i]) den += first_[i] + sum_[i] / frames_;
  if (!(den > 0.0)) throw InputError("flicker: no pixel is lit in any frame");
  return deviations_about_mean(luminance_, surface_, den);
}

std::vector<double> FlickerAccumulator::error_frame_deviations() const {
  if (frames_ < 2) throw InputError("flicker: needs at least 2 frames");
  if (reference_frames_ != frames_) throw InputError("flicker: the error flicker needs a reference for every frame");
  double den = 0;
  for (std::size_t i = 0; i < sum_.size(); ++i)
    if (surface_[i]) den += ref_sum_[i] / frames_;
  if (!(den > 0.0)) throw InputError("flicker: the reference is black in every frame");
  return deviations_about_mean(error_, surface_, den);
}

namespace {
// Population stdev from the sum and the sum of squares of deviations from a shift (the first
// frame): exactly 0 when every deviation is 0; clamped at 0 against rounding.
double stdev_of(double sum, double sum_sq, double n) {
  const double mean = sum / n;
  return std::sqrt(std::max(sum_sq / n - mean * mean, 0.0));
}
}  // namespace

double FlickerAccumulator::weighted_cv() const {
  if (frames_ < 2) throw InputError("flicker: needs at least 2 frames");
  const double n = frames_;
  double num = 0, den = 0;
  for (std::size_t i = 0; i < sum_.size(); ++i) {
    if (!surface_[i]) continue;
    num += stdev_of(sum_[i], sum_sq_[i], n);
    den += first_[i] + sum_[i] / n;  // the mean luminance
  }
  if (!(den > 0.0)) throw InputError("flicker: no pixel is lit in any frame");
  return num / den;
}

double FlickerAccumulator::error_cv() const {
  if (frames_ < 2) throw InputError("flicker: needs at least 2 frames");
  if (reference_frames_ != frames_) throw InputError("flicker: the error flicker needs a reference for every frame");
  const double n = frames_;
  double num = 0, den = 0;
  for (std::size_t i = 0; i < sum_.size(); ++i) {
    if (!surface_[i]) continue;
    num += stdev_of(err_sum_[i], err_sum_sq_[i], n);
    den += ref_sum_[i] / n;
  }
  if (!(den > 0.0)) throw InputError("flicker: the reference is black in every frame");
  return num / den;
}

double FlickerAccumulator::power_stdev() const {
  if (frames_ < 2) throw InputError("flicker: needs at least 2 frames");
  // The sample standard deviation (n - 1) of core/statistics.hpp, of the deviations from the first
  // frame's power (the same spread): exactly 0 when every frame has the same power.
  std::vector<double> deviations;
  for (double p : powers_) deviations.push_back(p - powers_.front());
  return summarize(deviations).stdev;
}

double FlickerAccumulator::power_relative_stdev() const {
  double sum = 0;
  for (double p : powers_) sum += p;
  const double mean = sum / static_cast<double>(powers_.size());
  if (!(mean > 0.0)) throw InputError("flicker: the mean total power is not positive");
  return power_stdev() / mean;
}

uint32_t frame_offset_bits(uint32_t frame) {
  uint32_t r = 0;
  for (int b = 0; b < 32; ++b) r |= ((frame >> b) & 1u) << (31 - b);
  return r;
}

}  // namespace vsgl
