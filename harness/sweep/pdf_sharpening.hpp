#pragma once
// The PDF-sharpness axis of `sweep` (DESIGN.md §10.1): a view's PDF raised to the power gamma, on a
// copy of the capture in memory, before upload. gamma = 1 is the capture's own PDF, gamma = 0 the
// uniform PDF over the same support (quality_metrics.hpp uniform_pdf_view), gamma > 1 sharper.
#include "harness/capture/capture.hpp"

namespace vsgl {

// q'(t) = (q(t) / max q)^gamma where the texel is valid and q(t) > 0, else 0. Dividing by the
// maximum first keeps every value in (0, 1] (no overflow for large gamma; the density p = q / q_bar
// does not change with the scale). A texel whose value underflows to 0 leaves the support, as its
// probability has. Throws InputError for a view without a PDF, an all-zero PDF, or gamma < 0 or
// not finite.
ViewImage sharpened_pdf_view(const ViewImage& view, double gamma);

// Both views' PDFs raised to gamma, and their hashes updated to the new planes.
Capture sharpened_pdf_capture(const Capture& capture, double gamma);

}  // namespace vsgl
