#include "harness/quality/flux_origin.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "harness/core/error.hpp"
#include "harness/quality/quality_metrics.hpp"

namespace vsgl {
namespace {

// q of level-0 texel i (row-major over the view) and the view's sum of q.
double texel_pdf(const MipPyramid& pdf, std::size_t i) {
  const uint32_t w = pdf.square.width;
  return static_cast<double>(pdf.at(0, static_cast<int32_t>(i % w), static_cast<int32_t>(i / w)).w);
}

double pdf_sum(const MipPyramid& pdf) {
  double s = 0;
  const std::size_t n = std::size_t{pdf.square.width} * pdf.square.height;
  for (std::size_t i = 0; i < n; ++i) s += texel_pdf(pdf, i);
  return s;
}

void check_sizes(const std::vector<float>& flux, const MipPyramid& pdf) {
  if (flux.size() != std::size_t{pdf.square.width} * pdf.square.height)
    throw InputError("flux origin: the flux and the PDF cover different texels");
}

}  // namespace

std::size_t flux_class(double q, double q_sum, uint32_t N) {
  if (!(q > 0.0)) return 0;
  const double e = static_cast<double>(N) * q / q_sum;
  std::size_t c = 1;
  for (double bound : kExpectedCentreBounds)
    if (e >= bound) ++c;
  return c;
}

std::vector<float> texel_flux(const std::vector<glm::vec4>& m0) {
  std::vector<float> f(m0.size());
  for (std::size_t i = 0; i < m0.size(); ++i) f[i] = m0[i].r + m0[i].g + m0[i].b;
  return f;
}

FluxByPdf flux_by_pdf(const std::vector<float>& texel_flux, const MipPyramid& pdf, uint32_t N) {
  check_sizes(texel_flux, pdf);
  const double q_sum = pdf_sum(pdf);
  if (!(q_sum > 0.0)) throw InputError("flux origin: the PDF is zero everywhere");
  FluxByPdf out;
  double total = 0;
  for (std::size_t i = 0; i < texel_flux.size(); ++i) {
    const double f = static_cast<double>(texel_flux[i]);
    if (!(f > 0.0)) continue;
    const std::size_t c = flux_class(texel_pdf(pdf, i), q_sum, N);
    ++out.texels[c];
    out.flux_share[c] += f;
    total += f;
  }
  if (!(total > 0.0)) throw InputError("flux origin: the view has no flux");
  for (double& s : out.flux_share) s /= total;
  return out;
}

FluxOrigin flux_origin(const std::vector<VsglRecord>& kernels, FisVariant variant, const std::vector<float>& texel_flux,
                       const MipPyramid& pdf, float K) {
  if (kernels.empty()) throw InputError("flux origin: no kernels");
  check_sizes(texel_flux, pdf);
  const auto N = static_cast<uint32_t>(kernels.size());
  FluxOrigin out;
  out.view = flux_by_pdf(texel_flux, pdf, N);
  const double M = static_cast<double>(pdf.square.square_texels());
  const double n = static_cast<double>(N);
  // The power coefficient M / D_i of each kernel (fis_power), in double from the recorded density.
  std::vector<double> weight(kernels.size()), oversized_weight(kernels.size(), 0.0);
  std::size_t oversized = 0;
  for (std::size_t i = 0; i < kernels.size(); ++i) {
    const double density = static_cast<double>(kernels[i].density());
    const double d = variant == FisVariant::kTok15 ? std::max(n * density, static_cast<double>(K)) : n * density;
    if (!(d > 0.0)) throw InputError("flux origin: kernel " + std::to_string(i) + " divides by a density of 0");
    weight[i] = M / d;
    const double mass = static_cast<double>(modified_kernel_mass(pdf, kernels[i].center(), kernels[i].level())) * n /
                        static_cast<double>(K);
    if (mass > kOversizedMass) {
      oversized_weight[i] = weight[i];
      ++oversized;
    }
  }
  out.oversized_kernels = static_cast<double>(oversized) / n;
  const std::vector<double> count = trilinear_footprint_sum(kernels, weight, pdf.square);
  const std::vector<double> count_oversized = trilinear_footprint_sum(kernels, oversized_weight, pdf.square);
  const double q_sum = pdf_sum(pdf);
  double total = 0, gathered = 0, q_count = 0;
  for (std::size_t i = 0; i < texel_flux.size(); ++i) {
    const double q = texel_pdf(pdf, i);
    q_count += q * count[i];
    const double f = static_cast<double>(texel_flux[i]);
    if (!(f > 0.0)) continue;
    const std::size_t c = flux_class(q, q_sum, N);
    total += f;
    gathered += f * count[i];
    out.gathered[c] += f * count[i];
    out.gathered_by_oversized[c] += f * count_oversized[i];
  }
  for (std::size_t c = 0; c < kFluxClasses; ++c) {
    out.gathered[c] /= total;
    out.gathered_by_oversized[c] /= total;
  }
  out.attributed_power_ratio = gathered / total;
  out.pdf_weighted_count = q_count / q_sum;
  return out;
}

}  // namespace vsgl
