#pragma once
// The pictures of the quality report (DESIGN.md §11a): Fig. 1 analogs (the PDF in grey, kernel centres in
// red, footprints in orange), error maps, and grids of tiles (Fig. 5 and Fig. 6 analogs). No text
// is drawn; the markdown report names the tiles in order.
#include <cstdint>
#include <vector>

#include "harness/reference/fis_reference.hpp"
#include "harness/quality/png_image.hpp"
#include "harness/math/vsgl_math.hpp"

namespace vsgl {

// The view's in-bounds W x H region, scaled so its longer side is at most `max_side` pixels: the
// PDF q as grey (sqrt of q / its 99th percentile over texels with q > 0, clamped), each kernel's
// footprint (side 2^l_i texels centred at x_i S, as in kernel_coverage()) outlined in orange and
// its centre as a red dot.
Rgb8Image coverage_picture(const MipPyramid& pdf_pyramid, const std::vector<VsglRecord>& kernels, uint32_t max_side);

// Box-filtered downscale by an integer factor (>= 1); pixels without a surface count as black.
RadianceImage downscale(const RadianceImage& image, uint32_t factor);

// |Y(image) - Y(reference)| / (full_scale * mean Y(reference)) as a heat ramp (black, red, yellow,
// white at 1 and above); grey where the reference has no surface. Sizes must match (InputError).
Rgb8Image error_map(const RadianceImage& image, const RadianceImage& reference, float full_scale);

// Tiles of equal size laid out row-major, `columns` per row, separated by a 4-pixel dark border.
// Throws InputError for no tiles or tiles of different sizes.
Rgb8Image tile_grid(const std::vector<Rgb8Image>& tiles, uint32_t columns);

}  // namespace vsgl
