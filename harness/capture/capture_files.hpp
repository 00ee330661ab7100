#pragma once
// A capture on disk (DESIGN.md §3, §12): two OpenEXR files and the JSON sidecar, written atomically and
// loaded with every value checked.
#include <filesystem>
#include <string>

#include "harness/capture/capture.hpp"

namespace vsgl {

// Writes DIR/gbuffer.exr, DIR/rsm.exr and DIR/capture.json, each through a temporary file and a
// rename, the sidecar last, so a reader sees either the old capture or the new one. Fills the
// hashes in the returned metadata.
CaptureMeta write_capture(const Capture& capture, const std::filesystem::path& dir);

// Loads and validates a capture (DESIGN.md §3, §12): sidecar present and well-formed, both EXR files
// readable, sizes and channel sets as the sidecar says, every value finite, valid flags 0/1,
// unit normals on valid texels, PDF non-negative and not all zero, hashes equal to the sidecar's.
// A capture whose BRSM PDF was made by another importance than this version's (DESIGN.md §8) is
// refused too. Throws InputError naming the file and the problem.
Capture load_capture(const std::filesystem::path& dir);

// Why a capture's BRSM PDF is not this version's (kBrsmImportanceModel at gpu::kBiasReductionAlpha),
// or empty when it is, or when the RSM has no PDF.
std::string brsm_importance_mismatch(const CaptureMeta& meta, bool rsm_has_pdf);

}  // namespace vsgl
