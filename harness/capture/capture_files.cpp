#include "harness/capture/capture_files.hpp"

#include <cmath>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "harness/capture/capture_sidecar.hpp"
#include "harness/capture/exr_io.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/core/text_format.hpp"

namespace vsgl {
namespace {

// Normals farther than this from unit length on a valid texel are rejected (DESIGN.md §12).
constexpr double kUnitNormalTolerance = 1e-3;

std::string texel_text(std::size_t index, uint32_t width) {
  return "texel (" + std::to_string(index % width) + ", " + std::to_string(index / width) + ")";
}

// Checks what write_capture needs of a view before anything touches the disk.
void check_view_for_writing(const ViewImage& view, ViewKind expected, const std::string& where) {
  if (view.kind != expected) {
    throw InputError(where + ": cannot write capture: the " + view_label(expected) +
                     " view has the wrong kind");
  }
  if (view.width == 0 || view.height == 0) {
    throw InputError(where + ": cannot write capture: the " + std::string(view_label(expected)) +
                     " image is empty (" + std::to_string(view.width) + "x" +
                     std::to_string(view.height) + ")");
  }
  if (expected == ViewKind::kCamera && !view.has_pdf) {
    throw InputError(where + ": cannot write capture: the camera view has no PDF; a capture "
                             "always carries the camera PDF (DESIGN.md §3)");
  }
  const auto names = channel_names(view.kind);
  for (int c = 0; c < stored_channel_count(view.has_pdf); ++c) {
    if (view.planes[c].size() != view.texels()) {
      throw InputError(where + ": cannot write capture: plane \"" + names[c] + "\" has " +
                       std::to_string(view.planes[c].size()) + " values, expected " +
                       std::to_string(view.texels()));
    }
  }
}

std::vector<char> encode_view(const ViewImage& view, const std::string& where) {
  std::vector<ExrChannelToWrite> channels;
  const auto names = channel_names(view.kind);
  for (int c = 0; c < stored_channel_count(view.has_pdf); ++c) {
    channels.push_back({names[c], view.planes[c], ExrSampleType::kFloat});
  }
  return encode_exr(view.width, view.height, channels, where);
}

// ---- EXR loading and value checks ---------------------------------------------------------------

ViewImage read_view_file(const std::filesystem::path& path, ViewKind kind,
                         const ViewRecord& record) {
  const std::string where = path_text(path);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw InputError(where + ": missing EXR file (" + kSidecarName + " lists it)");
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(where + ": the EXR file is not a regular file");
  }
  ExrImage image = read_exr(path, [&](uint32_t width, uint32_t height) {
    if (width != record.width || height != record.height) {
      throw InputError(where + ": image size " + std::to_string(width) + "x" +
                       std::to_string(height) + " differs from the size in " + kSidecarName +
                       ", " + std::to_string(record.width) + "x" + std::to_string(record.height));
    }
  });

  ViewImage view;
  view.resize(kind, record.width, record.height);
  view.has_pdf = record.has_pdf;
  const auto names = channel_names(kind);
  const int stored = stored_channel_count(record.has_pdf);
  for (const ExrChannelRead& channel : image.channels) {
    bool known = false;
    for (int c = 0; c < stored; ++c) known = known || channel.name == names[c];
    if (!known) {
      std::string why = channel.name == names[kPdf]
                            ? std::string(" (") + kSidecarName + " says has_pdf is false)"
                            : std::string();
      throw InputError(where + ": unexpected extra channel " + quoted_text(channel.name) + why);
    }
  }
  for (int c = 0; c < stored; ++c) {
    ExrChannelRead* channel = nullptr;
    for (ExrChannelRead& candidate : image.channels) {
      if (candidate.name == names[c]) channel = &candidate;
    }
    if (channel == nullptr) {
      std::string why = c == kPdf ? std::string(" (") + kSidecarName + " says has_pdf is true)"
                                  : std::string();
      throw InputError(where + ": missing channel \"" + names[c] + "\"" + why);
    }
    if (channel->type != ExrSampleType::kFloat) {
      throw InputError(where + ": channel \"" + names[c] + "\" is stored as " +
                       exr_sample_type_name(channel->type) + ", expected float (32-bit)");
    }
    view.planes[c] = std::move(channel->values);
  }
  return view;
}

void check_finite(const ViewImage& view, const std::string& where) {
  const auto names = channel_names(view.kind);
  for (int c = 0; c < kChannelCount; ++c) {
    const std::vector<float>& plane = view.planes[c];
    for (std::size_t i = 0; i < plane.size(); ++i) {
      if (std::isfinite(plane[i])) continue;
      const std::string what = std::isnan(plane[i]) ? "a NaN"
                               : plane[i] > 0.0f    ? "an infinite value (+Inf)"
                                                    : "an infinite value (-Inf)";
      throw InputError(where + ": channel \"" + names[c] + "\" has " + what + " at " +
                       texel_text(i, view.width) + "; every value must be finite");
    }
  }
}

void check_geometry(const ViewImage& view, const std::string& where) {
  const auto names = channel_names(view.kind);
  const std::vector<float>& valid = view.planes[kValid];
  for (std::size_t i = 0; i < valid.size(); ++i) {
    if (valid[i] != 0.0f && valid[i] != 1.0f) {
      throw InputError(where + ": channel \"" + names[kValid] + "\" is " +
                       number_text(static_cast<double>(valid[i])) + " at " +
                       texel_text(i, view.width) + "; the valid flag must be 0 or 1");
    }
    if (valid[i] == 0.0f) continue;  // an invalid texel's normal is unused
    const double nx = static_cast<double>(view.planes[kNX][i]);
    const double ny = static_cast<double>(view.planes[kNY][i]);
    const double nz = static_cast<double>(view.planes[kNZ][i]);
    const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
    if (std::abs(length - 1.0) > kUnitNormalTolerance) {
      throw InputError(where + ": the normal at " + texel_text(i, view.width) +
                       " is not unit length (|n| = " + number_text(length) +
                       "); valid texels need unit normals");
    }
  }
}

void check_pdf(const ViewImage& view, const std::string& where) {
  if (!view.has_pdf) return;
  const std::vector<float>& pdf = view.planes[kPdf];
  bool has_mass = false;
  for (std::size_t i = 0; i < pdf.size(); ++i) {
    if (pdf[i] < 0.0f) {
      throw InputError(where + ": channel \"pdf\" is negative (" +
                       number_text(static_cast<double>(pdf[i])) + ") at " +
                       texel_text(i, view.width) + "; a PDF is non-negative");
    }
    has_mass = has_mass || pdf[i] > 0.0f;
  }
  if (!has_mass) {
    throw InputError(where + ": all-zero PDF: the PDF has no mass, no texel can be sampled");
  }
}

void check_hashes(const ViewImage& view, const ViewRecord& record, const std::string& where) {
  const auto names = channel_names(view.kind);
  for (int c = 0; c < stored_channel_count(view.has_pdf); ++c) {
    const std::string actual = plane_hash(view.planes[c]);
    if (actual != record.hashes[c]) {
      throw InputError(where + ": channel \"" + names[c] + "\" hash mismatch: " + kSidecarName +
                       " records " + quoted_text(record.hashes[c]) + " but the file has " + actual +
                       "; the file changed since it was recorded");
    }
  }
}

ViewImage load_view(const std::filesystem::path& dir, ViewKind kind, const ViewRecord& record) {
  const std::filesystem::path path = dir / record.file;
  const std::string where = path_text(path);
  ViewImage view = read_view_file(path, kind, record);
  check_finite(view, where);
  check_geometry(view, where);
  check_pdf(view, where);
  check_hashes(view, record, where);
  return view;
}

}  // namespace

CaptureMeta write_capture(const Capture& capture, const std::filesystem::path& dir) {
  const std::filesystem::path gbuffer_path = dir / view_file_name(ViewKind::kCamera);
  const std::filesystem::path rsm_path = dir / view_file_name(ViewKind::kLight);
  const std::filesystem::path sidecar_path = dir / kSidecarName;
  check_view_for_writing(capture.gbuffer, ViewKind::kCamera, path_text(gbuffer_path));
  check_view_for_writing(capture.rsm, ViewKind::kLight, path_text(rsm_path));

  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw InputError(path_text(dir) + ": cannot create the capture directory: " +
                     (ec ? ec.message() : std::string("a file of that name is in the way")));
  }

  CaptureMeta meta = capture.meta;
  meta.gbuffer_hashes = {};
  meta.rsm_hashes = {};
  for (int c = 0; c < stored_channel_count(capture.gbuffer.has_pdf); ++c) {
    meta.gbuffer_hashes[c] = plane_hash(capture.gbuffer.planes[c]);
  }
  for (int c = 0; c < stored_channel_count(capture.rsm.has_pdf); ++c) {
    meta.rsm_hashes[c] = plane_hash(capture.rsm.planes[c]);
  }

  // The images and the visibility geometry first, the sidecar last: the sidecar's rename commits
  // the capture.
  write_file_atomic(gbuffer_path, encode_view(capture.gbuffer, path_text(gbuffer_path)));
  write_file_atomic(rsm_path, encode_view(capture.rsm, path_text(rsm_path)));
  meta.visibility_geometry.reset();
  if (capture.visibility_geometry) {
    const std::string bytes = encode_visibility_geometry(*capture.visibility_geometry);
    VisibilityGeometryRecord rec = visibility_geometry_record(*capture.visibility_geometry, bytes);
    write_file_atomic(dir / rec.file, bytes);
    meta.visibility_geometry = std::move(rec);
  }
  std::string sidecar;
  try {
    sidecar = sidecar_text(meta, capture);
  } catch (const nlohmann::ordered_json::exception& e) {  // e.g. a scene or device name that is not UTF-8
    throw InputError(path_text(sidecar_path) + ": cannot write the capture sidecar: " + e.what());
  }
  write_text_atomic(sidecar_path, sidecar);
  // A geometry file the new sidecar does not name is an older capture's: gone, so the directory
  // holds one capture.
  if (!meta.visibility_geometry) std::filesystem::remove(dir / kVisibilityGeometryFile, ec);
  return meta;
}

std::string brsm_importance_mismatch(const CaptureMeta& meta, bool rsm_has_pdf) {
  if (!rsm_has_pdf) return {};
  const std::string now =
      std::string(kBrsmImportanceModel) + " with alpha " + std::to_string(double{gpu::kBiasReductionAlpha});
  if (meta.brsm_importance.empty())
    return "its BRSM PDF was made by an older importance (the sidecar has no brsm_importance), not by this "
           "version's " +
           now;
  if (meta.brsm_importance != kBrsmImportanceModel || meta.brsm_bias_alpha != double{gpu::kBiasReductionAlpha})
    return "its BRSM PDF was made by " + meta.brsm_importance + " with alpha " + std::to_string(meta.brsm_bias_alpha) +
           ", not by this version's " + now;
  return {};
}

Capture load_capture(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::exists(dir, ec)) {
    throw InputError(path_text(dir) + ": capture directory does not exist");
  }
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(path_text(dir) + ": not a directory; a capture is a directory");
  }
  const std::filesystem::path sidecar_path = dir / kSidecarName;
  const SidecarContents sidecar = read_sidecar(sidecar_path);
  if (const std::string why = brsm_importance_mismatch(sidecar.meta, sidecar.rsm.has_pdf); !why.empty())
    throw InputError(path_text(sidecar_path) + ": " + why + "; record the capture again (vsgl-bench record)");
  Capture capture;
  capture.meta = sidecar.meta;
  capture.gbuffer = load_view(dir, ViewKind::kCamera, sidecar.gbuffer);
  capture.rsm = load_view(dir, ViewKind::kLight, sidecar.rsm);
  return capture;
}

}  // namespace vsgl
