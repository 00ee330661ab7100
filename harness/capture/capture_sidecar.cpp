#include "harness/capture/capture_sidecar.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "harness/core/error.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/text_format.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/printable_text.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;
using nlohmann::ordered_json;

constexpr const char* kFormatName = "vsgl-capture";
constexpr int kFormatVersion = 1;
constexpr const char* kCameraPdfName = "camera reflectance luminance";
constexpr const char* kRsmPdfName = "brsm";
constexpr const char* kNoPdfName = "none";
// A light direction farther than this from unit length is rejected.
constexpr double kUnitTolerance = 1e-3;
// The largest view a capture may hold (the paper's G-buffer is 1920x1088, 2 Mi texels): a
// sidecar that claims more is refused before any pixel memory is asked for (15 float planes of
// 32 Mi texels are already 2 GiB).
constexpr uint32_t kMaxViewSide = 16384;
constexpr uint64_t kMaxViewTexels = uint64_t{1} << 25;


// ---- Sidecar writing ---------------------------------------------------------------------------

ordered_json vec3_json(const glm::vec3& v) {
  return ordered_json::array(
      {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)});
}

// Column-major, as glm stores it: element [c][r] at index 4 c + r.
ordered_json mat4_json(const glm::mat4& m) {
  ordered_json out = ordered_json::array();
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) out.push_back(static_cast<double>(m[c][r]));
  }
  return out;
}

ordered_json view_json(const ViewImage& view, const std::array<std::string, kChannelCount>& hashes) {
  ordered_json channels = ordered_json::object();
  const auto names = channel_names(view.kind);
  for (int c = 0; c < stored_channel_count(view.has_pdf); ++c) channels[names[c]] = hashes[c];
  const char* pdf = view.kind == ViewKind::kCamera ? kCameraPdfName
                    : view.has_pdf                 ? kRsmPdfName
                                                   : kNoPdfName;
  ordered_json out;
  out["file"] = view_file_name(view.kind);
  out["width"] = view.width;
  out["height"] = view.height;
  out["has_pdf"] = view.has_pdf;
  out["pdf"] = pdf;
  out["channels"] = std::move(channels);
  return out;
}

}  // namespace

std::string sidecar_text(const CaptureMeta& meta, const Capture& capture) {
  ordered_json doc;
  doc["format"] = kFormatName;
  doc["format_version"] = kFormatVersion;
  doc["scene"] = meta.scene;
  doc["frame"] = meta.frame;
  doc["frames"] = meta.frames;
  doc["tool_version"] = meta.tool_version;
  doc["device"] = meta.device;
  doc["units"] = {{"length", "m"}, {"intensity", "W/sr"}, {"flux", "W"}};
  ordered_json camera;
  camera["position"] = vec3_json(meta.camera.position);
  camera["target"] = vec3_json(meta.camera.target);
  camera["up"] = vec3_json(meta.camera.up);
  camera["fov_y_deg"] = static_cast<double>(meta.camera.fov_y_deg);
  camera["near"] = static_cast<double>(meta.camera.near_plane);
  camera["far"] = static_cast<double>(meta.camera.far_plane);
  camera["view"] = mat4_json(meta.camera_view);
  camera["projection"] = mat4_json(meta.camera_projection);
  doc["camera"] = std::move(camera);
  ordered_json light;
  light["position"] = vec3_json(meta.light.position);
  light["direction"] = vec3_json(meta.light.direction);
  light["up"] = vec3_json(meta.light.up);
  light["cone_half_angle_deg"] = static_cast<double>(meta.light.cone_half_angle_deg);
  light["intensity"] = vec3_json(meta.light.intensity);
  light["near"] = static_cast<double>(meta.light.near_plane);
  light["far"] = static_cast<double>(meta.light.far_plane);
  light["view"] = mat4_json(meta.light_view);
  light["projection"] = mat4_json(meta.light_projection);
  doc["light"] = std::move(light);
  if (meta.source) {
    ordered_json source;
    source["format"] = meta.source->format;
    source["file"] = meta.source->file;
    source["content_hash"] = meta.source->content_hash;
    source["triangles"] = meta.source->triangles;
    source["camera"] = meta.source->camera;
    source["light"] = meta.source->light;
    if (!meta.source->preset.empty()) {
      source["preset"] = meta.source->preset;
      source["paper_table"] = meta.source->paper_table;
    }
    doc["source"] = std::move(source);
  }
  doc["brsm_build_ms"] = meta.brsm_build_ms;
  if (meta.brsm_pyramid) doc["brsm_pyramid"] = pyramid_path_name(*meta.brsm_pyramid);
  if (!meta.brsm_importance.empty())
    doc["brsm_importance"] = {{"model", meta.brsm_importance}, {"bias_reduction_alpha", meta.brsm_bias_alpha}};
  if (const auto& g = meta.visibility_geometry)
    doc["visibility_geometry"] = {{"file", g->file},
                                  {"triangles", g->triangles},
                                  {"points", g->points},
                                  {"point_seed", g->point_seed},
                                  {"hash", g->hash}};
  doc["gbuffer"] = view_json(capture.gbuffer, meta.gbuffer_hashes);
  doc["rsm"] = view_json(capture.rsm, meta.rsm_hashes);
  return doc.dump(2) + "\n";
}

namespace {

// ---- Sidecar reading ---------------------------------------------------------------------------

float read_real32(const JsonReader& reader, const json& object, const std::string& parent, const char* key) {
  return reader.number32(reader.member(object, parent, key), reader.child(parent, key));
}

glm::vec3 read_vec3(const JsonReader& reader, const json& object, const std::string& parent, const char* key) {
  const std::string path = reader.child(parent, key);
  const json& value = reader.array(object, parent, key, 3);
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = reader.number32(value[static_cast<std::size_t>(i)], reader.element(path, static_cast<std::size_t>(i)));
  return out;
}

// Column-major, as glm stores it: element [c][r] at index 4 c + r.
glm::mat4 read_mat4(const JsonReader& reader, const json& object, const std::string& parent, const char* key) {
  const std::string path = reader.child(parent, key);
  const json& value = reader.array(object, parent, key, 16);
  glm::mat4 out;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      const std::size_t index = static_cast<std::size_t>(4 * c + r);
      out[c][r] = reader.number32(value[index], reader.element(path, index));
    }
  return out;
}

json parse_sidecar(const std::filesystem::path& path) {
  const std::string where = path_text(path);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw InputError(where + ": missing capture sidecar (" + kSidecarName + " is not there)");
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(where + ": the capture sidecar is not a regular file");
  }
  json doc = read_json_file(path, "the capture sidecar");
  if (!doc.is_object()) {
    throw InputError(where + ": the capture sidecar is not a JSON object (it is a " +
                     doc.type_name() + ")");
  }
  return doc;
}

// The camera and light descriptions, with the ranges the generators rely on.
void read_camera(const JsonReader& reader, const json& doc, CaptureMeta& meta) {
  const json& camera = reader.object(doc, "", "camera");
  meta.camera.position = read_vec3(reader, camera, "camera", "position");
  meta.camera.target = read_vec3(reader, camera, "camera", "target");
  meta.camera.up = read_vec3(reader, camera, "camera", "up");
  meta.camera.fov_y_deg = read_real32(reader, camera, "camera", "fov_y_deg");
  meta.camera.near_plane = read_real32(reader, camera, "camera", "near");
  meta.camera.far_plane = read_real32(reader, camera, "camera", "far");
  meta.camera_view = read_mat4(reader, camera, "camera", "view");
  meta.camera_projection = read_mat4(reader, camera, "camera", "projection");
  if (!(meta.camera.fov_y_deg > 0.0f && meta.camera.fov_y_deg < 180.0f)) {
    reader.fail("", "key \"camera.fov_y_deg\" is " + number_text(meta.camera.fov_y_deg) +
                ", expected a value in (0, 180)");
  }
  if (!(meta.camera.near_plane > 0.0f && meta.camera.near_plane < meta.camera.far_plane)) {
    reader.fail("", "keys \"camera.near\" and \"camera.far\" must satisfy 0 < near < far");
  }
}

void read_light(const JsonReader& reader, const json& doc, CaptureMeta& meta) {
  const json& light = reader.object(doc, "", "light");
  meta.light.position = read_vec3(reader, light, "light", "position");
  meta.light.direction = read_vec3(reader, light, "light", "direction");
  meta.light.up = read_vec3(reader, light, "light", "up");
  meta.light.cone_half_angle_deg = read_real32(reader, light, "light", "cone_half_angle_deg");
  meta.light.intensity = read_vec3(reader, light, "light", "intensity");
  meta.light.near_plane = read_real32(reader, light, "light", "near");
  meta.light.far_plane = read_real32(reader, light, "light", "far");
  meta.light_view = read_mat4(reader, light, "light", "view");
  meta.light_projection = read_mat4(reader, light, "light", "projection");
  const double direction_length = static_cast<double>(glm::length(meta.light.direction));
  if (std::abs(direction_length - 1.0) > kUnitTolerance) {
    reader.fail("", "key \"light.direction\" is not a unit vector (length " +
                number_text(direction_length) + ")");
  }
  if (!(meta.light.cone_half_angle_deg > 0.0f && meta.light.cone_half_angle_deg < 90.0f)) {
    reader.fail("", "key \"light.cone_half_angle_deg\" is " +
                number_text(meta.light.cone_half_angle_deg) + ", expected a value in (0, 90)");
  }
  if (meta.light.intensity.r < 0.0f || meta.light.intensity.g < 0.0f ||
      meta.light.intensity.b < 0.0f) {
    reader.fail("", "key \"light.intensity\" has a negative component");
  }
  if (!(meta.light.near_plane > 0.0f && meta.light.near_plane < meta.light.far_plane)) {
    reader.fail("", "keys \"light.near\" and \"light.far\" must satisfy 0 < near < far");
  }
}

CaptureMeta read_meta(const JsonReader& reader, const json& doc) {
  const std::string format = reader.string(doc, "", "format");
  if (format != kFormatName) {
    reader.fail("", "key \"format\" is " + quoted_text(format) + ", expected \"" + kFormatName + "\"");
  }
  const uint32_t version = reader.uint32(doc, "", "format_version");
  if (version != kFormatVersion) {
    reader.fail("", "unsupported format_version " + std::to_string(version) + " (this tool reads " +
                std::to_string(kFormatVersion) + ")");
  }
  CaptureMeta meta;
  meta.scene = reader.string(doc, "", "scene");
  // The scene names output files (shade_<scene>_<generator>.png) and appears in messages: a
  // name, not a path.
  const bool scene_is_a_name =
      !meta.scene.empty() && meta.scene.size() <= 64 && meta.scene.front() != '.' &&
      meta.scene.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-") ==
          std::string::npos;
  if (!scene_is_a_name) {
    reader.fail("", "key \"scene\" is " + quoted_text(meta.scene) +
                ", expected a name of at most 64 letters, digits, '.', '_' or '-' (not starting with '.')");
  }
  meta.frame = reader.uint32(doc, "", "frame");
  meta.frames = reader.uint32(doc, "", "frames");
  if (meta.frames == 0 || meta.frame >= meta.frames) {
    reader.fail("", "key \"frame\" (" + std::to_string(meta.frame) + ") must be below \"frames\" (" +
                std::to_string(meta.frames) + ")");
  }
  meta.tool_version = reader.string(doc, "", "tool_version");
  meta.device = reader.string(doc, "", "device");
  const json& units = reader.object(doc, "", "units");
  const std::pair<const char*, const char*> expected_units[] = {
      {"length", "m"}, {"intensity", "W/sr"}, {"flux", "W"}};
  for (const auto& [quantity, unit] : expected_units) {
    const std::string found = reader.string(units, "units", quantity);
    if (found != unit) {
      reader.fail("", "key \"units." + std::string(quantity) + "\" is " + quoted_text(found) + ", expected \"" +
                  unit + "\"");
    }
  }
  read_camera(reader, doc, meta);
  read_light(reader, doc, meta);
  if (doc.contains("source")) {
    const json& source = reader.object(doc, "", "source");
    SceneSource src;
    src.format = reader.string(source, "source", "format");
    if (src.format != "gltf" && src.format != "obj")
      reader.fail("", "key \"source.format\" is " + quoted_text(src.format) + ", expected \"gltf\" or \"obj\"");
    src.file = reader.string(source, "source", "file");
    src.content_hash = reader.string(source, "source", "content_hash");
    src.triangles = reader.uint32(source, "source", "triangles");
    if (src.triangles == 0) reader.fail("", "key \"source.triangles\" is 0");
    src.camera = reader.string(source, "source", "camera");
    src.light = reader.string(source, "source", "light");
    if (source.contains("preset")) {
      src.preset = reader.string(source, "source", "preset");
      if (src.preset.empty()) reader.fail("", "key \"source.preset\" is empty");
      src.paper_table = reader.uint32(source, "source", "paper_table");
      if (src.paper_table > 2) reader.fail("", "key \"source.paper_table\" is " + std::to_string(src.paper_table) + ", expected 0, 1 or 2");
    }
    meta.source = std::move(src);
  }
  meta.brsm_build_ms = reader.number(doc, "", "brsm_build_ms");
  if (meta.brsm_build_ms < 0.0) reader.fail("", "key \"brsm_build_ms\" is negative");
  if (doc.contains("brsm_pyramid")) {
    const std::string path = reader.string(doc, "", "brsm_pyramid");
    meta.brsm_pyramid = parse_pyramid_path(path);
    if (!meta.brsm_pyramid)
      reader.fail("", "key \"brsm_pyramid\" is " + quoted_text(path) + ", expected \"buffer\" or \"texture\"");
  }
  if (doc.contains("brsm_importance")) {
    const json& importance = reader.object(doc, "", "brsm_importance");
    meta.brsm_importance = reader.string(importance, "brsm_importance", "model");
    meta.brsm_bias_alpha = reader.number(importance, "brsm_importance", "bias_reduction_alpha");
  }
  if (doc.contains("visibility_geometry")) {
    const json& g = reader.object(doc, "", "visibility_geometry");
    VisibilityGeometryRecord rec;
    rec.file = reader.string(g, "visibility_geometry", "file");
    // The file lies beside the sidecar: a name, never a path that could point elsewhere.
    if (rec.file.empty() || rec.file.find_first_of("/\\:") != std::string::npos || rec.file == "." || rec.file == "..")
      reader.fail("visibility_geometry", "key \"file\" must be a file name in the capture directory");
    rec.triangles = reader.uint64(g, "visibility_geometry", "triangles");
    rec.points = reader.uint64(g, "visibility_geometry", "points");
    rec.point_seed = reader.uint64(g, "visibility_geometry", "point_seed");
    rec.hash = reader.string(g, "visibility_geometry", "hash");
    meta.visibility_geometry = std::move(rec);
  }
  return meta;
}

ViewRecord read_view_record(const JsonReader& reader, const json& doc, ViewKind kind) {
  const std::string label = view_label(kind);
  const json& section = reader.object(doc, "", view_label(kind));
  ViewRecord record;
  record.file = reader.string(section, label, "file");
  if (record.file != view_file_name(kind)) {
    reader.fail("", "key \"" + label + ".file\" is " + quoted_text(record.file) + ", expected \"" +
                view_file_name(kind) + "\"");
  }
  record.width = reader.uint32(section, label, "width");
  record.height = reader.uint32(section, label, "height");
  if (record.width == 0 || record.height == 0) {
    reader.fail("", "keys \"" + label + ".width\" and \"" + label + ".height\" must be positive");
  }
  if (record.width > kMaxViewSide || record.height > kMaxViewSide ||
      uint64_t{record.width} * record.height > kMaxViewTexels) {
    reader.fail("", "keys \"" + label + ".width\" and \"" + label + ".height\" say " +
                std::to_string(record.width) + "x" + std::to_string(record.height) +
                ", larger than a capture may be (at most " + std::to_string(kMaxViewSide) +
                " per side and " + std::to_string(kMaxViewTexels) + " texels)");
  }
  record.has_pdf = reader.boolean(section, label, "has_pdf");
  if (kind == ViewKind::kCamera && !record.has_pdf) {
    reader.fail("", "key \"gbuffer.has_pdf\" is false; the camera PDF is required");
  }
  const std::string pdf = reader.string(section, label, "pdf");
  const char* expected_pdf = kind == ViewKind::kCamera ? kCameraPdfName
                             : record.has_pdf          ? kRsmPdfName
                                                       : kNoPdfName;
  if (pdf != expected_pdf) {
    reader.fail("", "key \"" + label + ".pdf\" is " + quoted_text(pdf) + ", expected \"" + expected_pdf +
                "\" (has_pdf is " + (record.has_pdf ? "true" : "false") + ")");
  }
  const json& channels = reader.object(section, label, "channels");
  const std::string channels_path = label + ".channels";
  const auto names = channel_names(kind);
  std::set<std::string> expected;
  for (int c = 0; c < stored_channel_count(record.has_pdf); ++c) {
    record.hashes[c] = reader.string(channels, channels_path, names[c]);
    expected.insert(names[c]);
  }
  for (const auto& item : channels.items()) {
    if (expected.count(item.key()) == 0) {
      reader.fail("", "key \"" + channels_path + "\" lists an unexpected channel " + quoted_text(item.key()));
    }
  }
  return record;
}

}  // namespace

SidecarContents read_sidecar(const std::filesystem::path& path) {
  const json doc = parse_sidecar(path);
  const JsonReader reader(path_text(path), JsonPathStyle::kDottedKey);
  SidecarContents out;
  out.meta = read_meta(reader, doc);
  out.gbuffer = read_view_record(reader, doc, ViewKind::kCamera);
  out.rsm = read_view_record(reader, doc, ViewKind::kLight);
  out.meta.gbuffer_hashes = out.gbuffer.hashes;
  out.meta.rsm_hashes = out.rsm.hashes;
  return out;
}

}  // namespace vsgl
