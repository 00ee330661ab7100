#pragma once
// The paper's quality claims as numbers (DESIGN.md §11a; the 2016 paper's Fig. 1, 5, 6): kernel coverage
// (gaps and overlaps of FIS footprints), the kernels' PDF mass against K/N, too-bright VSGLs,
// power conservation, image error against a reference, and temporal flicker. Pure CPU functions
// over downloaded VSGL records and radiance images, so tests can feed them known answers.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "harness/capture/capture.hpp"
#include "harness/core/statistics.hpp"
#include "harness/reference/fis_reference.hpp"
#include "harness/quality/radiance_image.hpp"
#include "harness/math/vsgl_math.hpp"

namespace vsgl {

// ---- Fig. 1: kernel footprints ---------------------------------------------------------------
// Kernel i's footprint is the square of side 2^l_i texels centred at x_i * S in the virtual
// square (DESIGN.md §4); it covers texel t when t's centre lies in [c - h, c + h)^2, h = 2^l_i / 2
// (half-open, so a level-0 footprint covers exactly one texel centre: the one nearest x_i).
struct KernelCoverage {
  double gap = 0;      // PDF-weighted fraction of the in-bounds texels covered by no footprint
  double overlap = 0;  // ... covered by two or more
  uint64_t texels_with_pdf = 0;
  uint64_t gap_texels = 0;      // texels with q > 0 and no footprint
  uint64_t overlap_texels = 0;  // texels with q > 0 and >= 2 footprints
  uint64_t covered_centres = 0;  // sum over all in-bounds texels of their footprint count
  // Kernel i's PDF mass a(l_i) p_bar(x_i, l_i) (Eq. 3's left side) times N / K: 1 is the target.
  std::vector<double> mass_ratio;
  SampleStats mass;  // of mass_ratio (core's summarize)
};
// Per in-bounds texel, how many footprints cover it (row-major W x H of the square's image).
std::vector<uint32_t> footprint_counts(const std::vector<VsglRecord>& kernels, const VirtualSquare& square);

// The footprint Eq. 3 controls: kernel i weighs level-0 texel t by k_i(t) = 4^l_i w_i(t), w_i the
// weights the trilinear lookup p_bar(x_i, l_i) gives t (bilinear taps at floor(l) and ceil(l),
// blended linearly, each level-l tap spread evenly over its 4^l children; taps outside a level's
// extent read zero, as in fetch()). Then sum_t k_i(t) p(t) / M is the kernel's mass a(l) p_bar
// (Eq. 3's left side); a level-l kernel centred on a level-l texel is exactly that texel's box.
// Its coverage n(t) = sum_i k_i(t) is also how many times texel t's flux enters the VSGLs' total
// power, for both estimators with K = 1 (Eq. 4 with N p >= K: M / (N p) = 4^l; Eq. 5:
// M / (N p_bar) = 4^l / K at the solved level), up to the level clamps at 0 and L.
std::vector<double> eq3_footprint_counts(const std::vector<VsglRecord>& kernels, const VirtualSquare& square);
// The general form: sum_i weights[i] w_i(t) per in-bounds level-0 texel t, w_i the trilinear
// weights above (they sum to 1 over a kernel inside the square). eq3_footprint_counts is this with
// weights 4^l_i; with weights M / D_i, D_i the density a FIS power divides by, it is how many times
// texel t's flux enters the total power (flux_origin.hpp). Raw sums: rounding residue of ~1e-16
// of the weights stays on texels no kernel reaches. Throws std::invalid_argument unless there is
// one weight per kernel, InputError for a record without a FIS level.
std::vector<double> trilinear_footprint_sum(const std::vector<VsglRecord>& kernels, const std::vector<double>& weights,
                                            const VirtualSquare& square);

// One footprint model's coverage, PDF-weighted over the texels with q > 0 (all over sum q):
//   gap = sum q max(1 - n, 0), surplus = sum q max(n - 1, 0),
//   count_error = sum q |n - 1| = gap + surplus (DESIGN.md §11a's count-weighted coverage error),
//   mean_count = sum q n. For the box footprint n is an integer, so its gap is the share with n = 0.
struct CoverageCounts {
  double gap = 0, surplus = 0, count_error = 0, mean_count = 0;
};
CoverageCounts coverage_counts(const std::vector<double>& n, const MipPyramid& pdf_pyramid);

// Throws InputError when a record has no FIS level (k-means records carry -1) or the PDF is zero.
KernelCoverage kernel_coverage(const std::vector<VsglRecord>& kernels, const MipPyramid& pdf_pyramid, float K);

// Both footprint models of one kernel set: box (side 2^l, the squares Fig. 1 draws; `coverage`
// holds its binary gap and overlap and the kernels' mass) and Eq. 3's trilinear weights.
struct FootprintCoverage {
  KernelCoverage coverage;
  CoverageCounts box;
  CoverageCounts eq3;
};
FootprintCoverage footprint_coverage(const std::vector<VsglRecord>& kernels, const MipPyramid& pdf_pyramid, float K);

// ---- the lattice's own floor (DESIGN.md §11a) ----------------------------------------------------
// The view with its PDF replaced by 1 on every texel the coverage weighs (valid and q > 0) and 0
// elsewhere: the same generator and N on it show the Fibonacci lattice's own irregularity and the
// support's shape, which no kernel-size choice can remove. A view whose PDF is already 0/1 on
// those texels is returned bit for bit, so its excess over the floor is exactly 0.
ViewImage uniform_pdf_view(const ViewImage& view);
// Generator minus floor, measure by measure.
struct CoverageExcess {
  CoverageCounts box, eq3;
  double box_gap = 0, box_overlap = 0;  // the binary gap and overlap of KernelCoverage
};
CoverageExcess coverage_excess(const FootprintCoverage& generator, const FootprintCoverage& floor);

// ---- how high-frequency a PDF is (DESIGN.md §11a) ------------------------------------------------
// The Haar wavelet spectrum of the PDF over the virtual square, on the mip levels FIS filters:
// with p = q / q_bar_L (mean 1 over the square) and p_bar_l its level-l box mean, the detail
// energy of level l is E_l = (1/M) sum_t (p_bar_l(t) - p_bar_{l+1}(t))^2 over level-0 texels t.
// The details are orthogonal, so mean(p^2) = 1 + sum_l E_l exactly; level l's detail holds
// wavelengths of about 2^(l+1) texels (frequencies near 1 / 2^(l+1) cycles per texel).
struct PdfFrequency {
  std::vector<double> detail_energy;  // E_0 .. E_{L-1}
  double mean_square = 0;             // mean of p^2 over the square (1 + sum E_l)
  double relative_variance = 0;       // sum E_l = var(p) (p has mean 1)
  // Share of the energy mean(p^2) at wavelengths below 2^(k+1) texels: (E_0 + ... + E_k) / mean(p^2),
  // k = 0 .. L-1; 0 for a uniform PDF, near 1/2 for a texel checkerboard of 1 and 0.
  std::vector<double> fine_share;
};
// Throws InputError for a PDF that is zero everywhere.
PdfFrequency pdf_frequency(const MipPyramid& pdf_pyramid);

// ---- Fig. 5: too-bright VSGLs, and power ----------------------------------------------------
// Scalar power of a VSGL: Phi.r + Phi.g + Phi.b (the light view's moment weight w, DESIGN.md §4).
float scalar_power(const VsglRecord& v);
struct PowerMetrics {
  double total_vsgl_power = 0;  // sum_i Phi_i
  double total_flux = 0;        // sum over the view's texels of their Phi (rgb summed)
  double power_ratio = 0;       // sum_i Phi_i / total flux
  double max_over_mean = 0;     // max_i Phi_i / (sum Phi / N)
  double p99_over_mean = 0;     // 99th percentile of Phi_i / (sum Phi / N)
};
// Throws InputError for no VSGLs, a non-positive total flux or a non-positive VSGL power sum.
PowerMetrics power_metrics(const std::vector<VsglRecord>& vsgls, double total_flux);
// Sum of Phi.rgb over the M0 layer of a view (reference_moments()[0]).
double total_flux(const std::vector<glm::vec4>& m0);

// ---- Error against a reference ---------------------------------------------------------------
// The Rec. 709 luminance of a radiance pixel (alpha ignored), in double for the sums below.
double pixel_luminance(glm::vec4 p);
// The mean luminance of the pixels with a surface (alpha > 0); 0 where there is none. The
// reference ladder records it per rung (DESIGN.md §11a): a reference that leaks light through a
// near-field tail brightens as its RSM grows, one that converges stays flat.
double mean_surface_luminance(const RadianceImage& image);
struct ImageError {
  double relative_rmse = 0;  // sqrt(sum |L - R|^2 / sum |R|^2) over rgb of the pixels with a surface
  // 99th percentile over those pixels of |Y(L) - Y(R)| / mean Y(R) (luminance, relative to the
  // reference's mean luminance, so the number is independent of the light's intensity).
  double p99_pixel_error = 0;
};
// Throws InputError for images of different sizes or a black reference.
ImageError image_error(const RadianceImage& image, const RadianceImage& reference);

// ---- Flicker ---------------------------------------------------------------------------------
// Accumulates F shaded frames of the same pixels and each frame's total VSGL power. Per pixel,
// the temporal coefficient of variation of the luminance is sigma_p / mu_p (population stdev);
// its luminance-weighted mean over the pixels with a surface is sum_p sigma_p / sum_p mu_p.
class FlickerAccumulator {
 public:
  // Throws InputError when a frame's size differs from the first one.
  void add_frame(const RadianceImage& image, double total_power);
  // Optional: a per-frame reference of the same pixels, for the error flicker below.
  void add_frame(const RadianceImage& image, double total_power, const RadianceImage& reference);

  uint32_t frames() const { return frames_; }
  // Luminance-weighted mean temporal CV (0 when every frame is identical). Throws InputError for
  // fewer than 2 frames or images without a lit pixel.
  double weighted_cv() const;
  // Sample standard deviation (n - 1) of the per-frame total power, and that divided by its mean.
  double power_stdev() const;
  double power_relative_stdev() const;
  // With references: sum_p stdev_t(Y_t(p) - Yref_t(p)) / sum_p mean_t(Yref_t(p)) — the part of the
  // frame-to-frame change that the reference does not have. Throws InputError without references.
  double error_cv() const;
  // Per frame f, delta_f = sum_p |Y_f(p) - mu(p)| / sum_p mu(p), mu the pixel's mean over the
  // frames (DESIGN.md §11a.1): the frame's share of the flicker, a value two generators' frames
  // pair on. The error's: the same of Y_f - Yref_f about its mean, over sum_p mean_t Yref_t(p).
  // Throw as weighted_cv and error_cv do.
  std::vector<double> frame_deviations() const;
  std::vector<double> error_frame_deviations() const;

 private:
  void check_size(const RadianceImage& image);
  uint32_t frames_ = 0, width_ = 0, height_ = 0, reference_frames_ = 0;
  std::vector<double> first_, sum_, sum_sq_;  // per pixel: first frame's luminance, deviation sums
  std::vector<double> err_first_, err_sum_, err_sum_sq_, ref_sum_;
  std::vector<std::vector<float>> luminance_, error_;  // per frame, per pixel: Y and Y - Yref
  std::vector<uint8_t> surface_;              // 1 where every frame had a surface
  std::vector<double> powers_;
};

// Van der Corput offsets for frame f (bit-reversed f as 32-bit fixed point): 0 for frame 0, then
// well spread in [0, 1), so F frames cover the lattice's offsets evenly (DESIGN.md §5).
uint32_t frame_offset_bits(uint32_t frame);

}  // namespace vsgl
