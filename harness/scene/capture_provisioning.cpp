#include "harness/scene/capture_provisioning.hpp"

#include <chrono>
#include <nlohmann/json.hpp>

#include "harness/capture/capture_files.hpp"
#include "harness/capture/capture_sidecar.hpp"
#include "harness/core/error.hpp"
#include "harness/core/sorted_json.hpp"
#include "harness/scene/brsm_pdf.hpp"
#include "harness/scene/scene.hpp"
#include "harness/scene/visibility_recording.hpp"

namespace vsgl {

namespace {

double plane_sum(const std::vector<float>& plane) {
  double sum = 0.0;
  for (float v : plane) sum += static_cast<double>(v);
  return sum;
}

// What would make every generator's input empty, named in terms of the scene.
void refuse_empty_views(const Capture& capture, const std::string& scene, bool with_brsm) {
  const std::string where = "scene '" + scene + "': ";
  if (plane_sum(capture.gbuffer.planes[kValid]) == 0.0)
    throw InputError(where + "the camera sees no surface (every G-buffer texel is empty): choose another camera");
  if (plane_sum(capture.rsm.planes[kValid]) == 0.0)
    throw InputError(where + "the spot light reaches no surface (every RSM texel is empty): choose another light");
  if (plane_sum(capture.gbuffer.planes[kPdf]) == 0.0)
    throw InputError(where + "the camera PDF is zero everywhere (every surface the camera sees is black)");
  if (with_brsm && plane_sum(capture.rsm.planes[kPdf]) == 0.0)
    throw InputError(where + "the BRSM PDF is zero everywhere: no flux the light brings reaches what the camera "
                     "sees (is the cone outside the camera's view, or are the lit surfaces black?)");
}

}  // namespace

RecordedCapture record_capture(Device& device, const Scene& scene, const RecordSizes& sizes, uint32_t frame,
                               uint32_t frames, const std::filesystem::path& dir,
                               const std::optional<SceneSource>& source) {
  const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  RecordedCapture out;
  const auto t0 = std::chrono::steady_clock::now();
  CaptureRecorder recorder(device);
  out.capture = recorder.record(scene, sizes, frame, frames);
  out.capture.meta.source = source;
  if (sizes.visibility_points > 0)
    out.capture.visibility_geometry = scene_visibility_geometry(scene, sizes.visibility_points, kVisibilityPointSeed);
  refuse_empty_views(out.capture, scene.name, false);
  const BrsmBuild brsm = build_brsm_pdf(device, out.capture);  // DESIGN.md §8: once per capture
  refuse_empty_views(out.capture, scene.name, true);
  const auto t1 = std::chrono::steady_clock::now();
  out.capture.meta = write_capture(out.capture, dir);
  const auto t2 = std::chrono::steady_clock::now();
  out.render_and_brsm_ms = ms(t0, t1);
  out.brsm_gpu_ms = brsm.gpu_ms;
  out.brsm_camera_vsgls = brsm.camera_vsgls;
  out.write_ms = ms(t1, t2);
  return out;
}

RecordedCapture record_scene_capture(Device& device, const NamedScene& scene, const RecordSizes& sizes, uint32_t frame,
                                     uint32_t frames, const std::filesystem::path& dir) {
  return record_capture(device, scene.frame(frame, frames), sizes, frame, frames, dir, scene.source);
}

RecordedCapture record_scene_capture(Device& device, const std::string& scene_name, const RecordSizes& sizes,
                                     uint32_t frame, uint32_t frames, const std::filesystem::path& dir) {
  return record_capture(device, make_scene(scene_name, frame, frames), sizes, frame, frames, dir);
}

ProvidedCapture provide_capture(Device& device, const NamedScene& scene, const RecordSizes& sizes,
                                const std::filesystem::path& dir) {
  ProvidedCapture out;
  if (std::filesystem::exists(dir / kSidecarName)) {
    const SidecarContents on_disk = read_sidecar(dir / kSidecarName);  // a broken sidecar is an error
    out.stale_because =
        capture_staleness(on_disk.meta, on_disk.gbuffer.width, on_disk.gbuffer.height, on_disk.rsm.width, scene, sizes);
  }
  if (!std::filesystem::exists(dir / kSidecarName) || !out.stale_because.empty()) {
    std::filesystem::create_directories(dir);
    record_scene_capture(device, scene, sizes, 0, 1, dir);
    out.recorded = true;
  }
  // Always the loaded bytes: what is timed is exactly what is on disk and hashed.
  out.capture = load_capture(dir);
  return out;
}

nlohmann::ordered_json capture_hashes_json(const Capture& capture) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  const auto add = [&](ViewKind kind, const std::array<std::string, kChannelCount>& hashes, bool has_pdf) {
    nlohmann::ordered_json view = nlohmann::ordered_json::object();
    const auto names = channel_names(kind);
    for (int c = 0; c < kChannelCount; ++c) {
      if (c == kPdf && !has_pdf) continue;
      view[names[static_cast<std::size_t>(c)]] = hashes[static_cast<std::size_t>(c)];
    }
    out[view_label(kind)] = view;
  };
  add(ViewKind::kCamera, capture.meta.gbuffer_hashes, capture.gbuffer.has_pdf);
  add(ViewKind::kLight, capture.meta.rsm_hashes, capture.rsm.has_pdf);
  return sorted_keys(out);
}

}  // namespace vsgl
