#pragma once
// A reference capture (DESIGN.md §11a, `quality --reference-capture`): the same frame recorded a
// second time with a larger RSM, whose texels become the reference's VPLs while the generators keep
// the capture's own RSM, so the reference's convergence can be followed past the generators' RSM.
// On Sponza its own error falls only about 0.9x per doubling of the side (DESIGN.md §11a, the
// reference ladder).
#include <string>

#include "harness/capture/capture.hpp"

namespace vsgl {

// Throws InputError, naming the first difference, unless `reference` (read from `reference_dir`)
// shows the same frame as `capture`: the same scene (and model content hash), camera, light and
// view matrices, a G-buffer of the same size with the same channel hashes (so the reference shades
// the generators' very pixels), and an RSM with a BRSM PDF at least as large as the capture's.
void check_reference_capture(const Capture& capture, const Capture& reference, const std::string& reference_dir);

}  // namespace vsgl
