#pragma once
// Making a capture exist on disk: the one code path of `vsgl-bench record` (rasterize, build the
// BRSM PDF once per capture (DESIGN.md §8), write atomically), shared by `tables`, which records the
// paper's captures when they are missing and otherwise loads and validates them.
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "harness/capture/capture.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/scene/named_scene.hpp"
#include "harness/scene/scene.hpp"

namespace vsgl {

class Device;

struct RecordedCapture {
  Capture capture;
  double render_and_brsm_ms = 0;  // wall time: rasterization + BRSM PDF
  double brsm_gpu_ms = 0;         // GPU time of the BRSM PDF build
  uint32_t brsm_camera_vsgls = 0;
  double write_ms = 0;
};

// Renders frame `frame` of `frames` of `scene`, builds its BRSM PDF and writes it to `dir`, the
// sidecar naming `source` (a user's file) when given. A capture in which the generators would
// have nothing to work on is refused before anything is written (InputError): a camera or a
// light that sees no surface, an all-zero camera PDF or BRSM PDF.
RecordedCapture record_capture(Device& device, const Scene& scene, const RecordSizes& sizes, uint32_t frame,
                               uint32_t frames, const std::filesystem::path& dir,
                               const std::optional<SceneSource>& source = std::nullopt);

// record_capture() of a named scene (a procedural scene or a preset's model); the sidecar names
// the preset's model as its source.
RecordedCapture record_scene_capture(Device& device, const NamedScene& scene, const RecordSizes& sizes, uint32_t frame,
                                     uint32_t frames, const std::filesystem::path& dir);
// ... of the procedural scene `scene`. Throws InputError for an unknown scene.
RecordedCapture record_scene_capture(Device& device, const std::string& scene, const RecordSizes& sizes, uint32_t frame,
                                     uint32_t frames, const std::filesystem::path& dir);

struct ProvidedCapture {
  Capture capture;
  bool recorded = false;      // true when it was recorded now
  std::string stale_because;  // why the capture found in the directory was re-recorded; empty if it was not
};

// The capture of `scene` at `sizes` in `dir`, a cache keyed by scene, sizes, model content, camera
// and light: loaded when the sidecar there matches all of them (load_capture: every hash checked),
// else recorded there first, replacing a stale one (capture_staleness says why). A capture that is
// broken is an error (InputError), never silently re-recorded.
ProvidedCapture provide_capture(Device& device, const NamedScene& scene, const RecordSizes& sizes,
                                const std::filesystem::path& dir);

// Every channel hash of both views, as the sidecar has them: {"gbuffer": {channel: hash}, "rsm": ...},
// the keys sorted, as the tables, quality reports and their hashes of it always had them.
nlohmann::ordered_json capture_hashes_json(const Capture& capture);

}  // namespace vsgl
