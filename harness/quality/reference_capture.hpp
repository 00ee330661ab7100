#pragma once
// A reference capture (DESIGN.md §11a, `quality --reference-capture`): the same frame recorded a
// second time with a larger RSM, whose texels become the reference's VPLs while the generators keep
// the capture's own RSM. The reference's error against the continuum falls about linearly with the
// RSM texel size (the convergence table), so a capture at the paper's 512^2 RSM cannot converge its
// own reference; a GPU can shade one from 4096^2 texels in seconds.
#include <string>

#include "harness/capture/capture.hpp"

namespace vsgl {

// Throws InputError, naming the first difference, unless `reference` (read from `reference_dir`)
// shows the same frame as `capture`: the same scene (and model content hash), camera, light and
// view matrices, a G-buffer of the same size with the same channel hashes (so the reference shades
// the generators' very pixels), and an RSM with a BRSM PDF at least as large as the capture's.
void check_reference_capture(const Capture& capture, const Capture& reference, const std::string& reference_dir);

}  // namespace vsgl
