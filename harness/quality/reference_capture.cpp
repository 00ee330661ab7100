#include "harness/quality/reference_capture.hpp"

#include "harness/core/error.hpp"

namespace vsgl {
namespace {

std::string size_text(const ViewImage& v) { return std::to_string(v.width) + "x" + std::to_string(v.height); }

bool same_camera(const CameraDesc& a, const CameraDesc& b) {
  return a.position == b.position && a.target == b.target && a.up == b.up && a.fov_y_deg == b.fov_y_deg &&
         a.near_plane == b.near_plane && a.far_plane == b.far_plane;
}

bool same_light(const SpotLightDesc& a, const SpotLightDesc& b) {
  return a.position == b.position && a.direction == b.direction && a.up == b.up &&
         a.cone_half_angle_deg == b.cone_half_angle_deg && a.intensity == b.intensity && a.near_plane == b.near_plane &&
         a.far_plane == b.far_plane;
}

}  // namespace

void check_reference_capture(const Capture& capture, const Capture& reference, const std::string& reference_dir) {
  const std::string who = "quality: the reference capture " + reference_dir;
  const std::string record_hint =
      "; record it with the same `vsgl-bench record` options (scene, --gbuffer, device) and a larger --rsm";
  const CaptureMeta& a = capture.meta;
  const CaptureMeta& b = reference.meta;
  if (a.scene != b.scene)
    throw InputError(who + " shows scene '" + b.scene + "', the capture '" + a.scene + "'" + record_hint);
  const std::string hash_a = a.source ? a.source->content_hash : "", hash_b = b.source ? b.source->content_hash : "";
  if (hash_a != hash_b)
    throw InputError(who + " was recorded from another model file (content hash " + (hash_b.empty() ? "none" : hash_b) +
                     ", the capture's " + (hash_a.empty() ? "none" : hash_a) + ")" + record_hint);
  if (reference.gbuffer.width != capture.gbuffer.width || reference.gbuffer.height != capture.gbuffer.height)
    throw InputError(who + " has a " + size_text(reference.gbuffer) + " G-buffer, the capture " +
                     size_text(capture.gbuffer) + record_hint);
  if (!same_camera(a.camera, b.camera) || a.camera_view != b.camera_view || a.camera_projection != b.camera_projection)
    throw InputError(who + " has another camera" + record_hint);
  if (!same_light(a.light, b.light) || a.light_view != b.light_view || a.light_projection != b.light_projection)
    throw InputError(who + " has another light" + record_hint);
  for (int c = 0; c < kChannelCount; ++c)
    if (a.gbuffer_hashes[c] != b.gbuffer_hashes[c])
      throw InputError(who + ": its G-buffer differs from the capture's in channel '" +
                       channel_names(ViewKind::kCamera)[c] +
                       "', so the reference would not shade the generators' pixels" + record_hint);
  if (reference.rsm.width < capture.rsm.width || reference.rsm.height < capture.rsm.height)
    throw InputError(who + " has a " + size_text(reference.rsm) + " RSM, smaller than the capture's " +
                     size_text(capture.rsm) + ": its VPLs would be coarser than the generators' input" + record_hint);
  if (!reference.rsm.has_pdf)
    throw InputError(who + " has no BRSM PDF (the PDF-support reference needs it)" + record_hint);
}

}  // namespace vsgl
