#include "harness/sweep/pdf_sharpening.hpp"

#include <algorithm>
#include <cmath>

#include "harness/core/error.hpp"
#include "harness/core/text_format.hpp"

namespace vsgl {

ViewImage sharpened_pdf_view(const ViewImage& view, double gamma) {
  if (!std::isfinite(gamma) || gamma < 0)
    throw InputError("PDF sharpness " + number_text(gamma) + ": gamma must be a finite number >= 0");
  const std::vector<float>& q = view.planes[kPdf];
  const std::vector<float>& valid = view.planes[kValid];
  if (!view.has_pdf || q.size() != view.texels() || valid.size() != view.texels())
    throw InputError(std::string(view_label(view.kind)) + ": the view has no PDF to sharpen");
  float top = 0;
  for (std::size_t i = 0; i < q.size(); ++i)
    if (valid[i] != 0.0f) top = std::max(top, q[i]);
  if (!(top > 0)) throw InputError(std::string(view_label(view.kind)) + ": the PDF is zero everywhere");
  ViewImage out = view;
  std::vector<float>& p = out.planes[kPdf];
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool support = valid[i] != 0.0f && q[i] > 0.0f;
    p[i] = support ? static_cast<float>(std::pow(static_cast<double>(q[i]) / static_cast<double>(top), gamma)) : 0.0f;
  }
  return out;
}

Capture sharpened_pdf_capture(const Capture& capture, double gamma) {
  Capture out = capture;
  out.gbuffer = sharpened_pdf_view(capture.gbuffer, gamma);
  out.rsm = sharpened_pdf_view(capture.rsm, gamma);
  out.meta.gbuffer_hashes[kPdf] = plane_hash(out.gbuffer.planes[kPdf]);
  out.meta.rsm_hashes[kPdf] = plane_hash(out.rsm.planes[kPdf]);
  return out;
}

}  // namespace vsgl
