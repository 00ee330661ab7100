#include "harness/capture.hpp"

#include <bit>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "harness/atomic_file.hpp"
#include "harness/error.hpp"
#include "harness/exr_io.hpp"
#include "harness/printable_text.hpp"

namespace vsgl {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr const char* kSidecarName = "capture.json";
constexpr const char* kFormatName = "vsgl-capture";
constexpr int kFormatVersion = 1;
constexpr const char* kCameraPdfName = "camera reflectance luminance";
constexpr const char* kRsmPdfName = "brsm";
constexpr const char* kNoPdfName = "none";
// Normals farther than this from unit length on a valid texel are rejected (SPEC §12).
constexpr double kUnitNormalTolerance = 1e-3;
// The largest view a capture may hold (the paper's G-buffer is 1920x1088, 2 Mi texels): a
// sidecar that claims more is refused before any pixel memory is asked for (15 float planes of
// 32 Mi texels are already 2 GiB).
constexpr uint32_t kMaxViewSide = 16384;
constexpr uint64_t kMaxViewTexels = uint64_t{1} << 25;

constexpr std::array<const char*, kChannelCount> kCameraChannelNames = {
    "P.X", "P.Y", "P.Z", "valid", "N.X", "N.Y", "N.Z", "albedo_diffuse.R", "albedo_diffuse.G",
    "albedo_diffuse.B", "albedo_specular.R", "albedo_specular.G", "albedo_specular.B", "roughness",
    "pdf"};
constexpr std::array<const char*, kChannelCount> kLightChannelNames = {
    "P.X", "P.Y", "P.Z", "valid", "N.X", "N.Y", "N.Z", "flux_diffuse.R", "flux_diffuse.G",
    "flux_diffuse.B", "flux_specular.R", "flux_specular.G", "flux_specular.B", "roughness", "pdf"};

// Channels stored in the file: all of them, less the PDF when the view has none.
int stored_channel_count(bool has_pdf) { return has_pdf ? kChannelCount : kPdf; }

std::string number_text(double value) {
  std::ostringstream out;
  out.precision(9);
  out << value;
  return out.str();
}

std::string texel_text(std::size_t index, uint32_t width) {
  return "texel (" + std::to_string(index % width) + ", " + std::to_string(index / width) + ")";
}

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
  doc["brsm_build_ms"] = meta.brsm_build_ms;
  doc["gbuffer"] = view_json(capture.gbuffer, meta.gbuffer_hashes);
  doc["rsm"] = view_json(capture.rsm, meta.rsm_hashes);
  return doc.dump(2) + "\n";
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
                             "always carries the camera PDF (SPEC §3)");
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

// ---- Sidecar reading ---------------------------------------------------------------------------

// Typed access to the sidecar, every failure naming the file and the dotted key.
class SidecarReader {
 public:
  explicit SidecarReader(std::string where) : where_(std::move(where)) {}

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(where_ + ": " + problem);
  }

  static std::string key_path(const std::string& parent, const char* key) {
    return parent.empty() ? std::string(key) : parent + "." + key;
  }

  const json& member(const json& object, const std::string& parent, const char* key) const {
    auto it = object.find(key);
    if (it == object.end()) fail("key \"" + key_path(parent, key) + "\" is missing");
    return *it;
  }

  [[noreturn]] void wrong_type(const json& value, const std::string& path,
                               const char* expected) const {
    fail("key \"" + path + "\" has type " + value.type_name() + ", expected " + expected);
  }

  const json& object(const json& object, const std::string& parent, const char* key) const {
    const json& value = member(object, parent, key);
    if (!value.is_object()) wrong_type(value, key_path(parent, key), "an object");
    return value;
  }

  std::string string(const json& object, const std::string& parent, const char* key) const {
    const json& value = member(object, parent, key);
    if (!value.is_string()) wrong_type(value, key_path(parent, key), "a string");
    return value.get<std::string>();
  }

  bool boolean(const json& object, const std::string& parent, const char* key) const {
    const json& value = member(object, parent, key);
    if (!value.is_boolean()) wrong_type(value, key_path(parent, key), "a boolean");
    return value.get<bool>();
  }

  uint32_t uint32(const json& object, const std::string& parent, const char* key) const {
    const json& value = member(object, parent, key);
    // nlohmann parses every non-negative integer literal as number_unsigned.
    if (!value.is_number_unsigned() ||
        value.get<unsigned long long>() > std::numeric_limits<uint32_t>::max()) {
      wrong_type(value, key_path(parent, key), "an unsigned 32-bit integer");
    }
    return static_cast<uint32_t>(value.get<unsigned long long>());
  }

  double real(const json& object, const std::string& parent, const char* key) const {
    return finite_number(member(object, parent, key), key_path(parent, key));
  }

  float real32(const json& object, const std::string& parent, const char* key) const {
    return to_float(real(object, parent, key), key_path(parent, key));
  }

  glm::vec3 vec3(const json& object, const std::string& parent, const char* key) const {
    const std::string path = key_path(parent, key);
    const json& value = member(object, parent, key);
    expect_array(value, path, 3);
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
      const std::string element = path + "[" + std::to_string(i) + "]";
      out[i] = to_float(finite_number(value[static_cast<std::size_t>(i)], element), element);
    }
    return out;
  }

  glm::mat4 mat4(const json& object, const std::string& parent, const char* key) const {
    const std::string path = key_path(parent, key);
    const json& value = member(object, parent, key);
    expect_array(value, path, 16);
    glm::mat4 out;
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        const std::size_t index = static_cast<std::size_t>(4 * c + r);
        const std::string element = path + "[" + std::to_string(index) + "]";
        out[c][r] = to_float(finite_number(value[index], element), element);
      }
    }
    return out;
  }

 private:
  void expect_array(const json& value, const std::string& path, std::size_t count) const {
    const std::string expected = "an array of " + std::to_string(count) + " numbers";
    if (!value.is_array()) wrong_type(value, path, expected.c_str());
    if (value.size() != count) {
      fail("key \"" + path + "\" has " + std::to_string(value.size()) + " elements, expected " +
           expected);
    }
  }

  double finite_number(const json& value, const std::string& path) const {
    if (!value.is_number()) wrong_type(value, path, "a number");
    const double number = value.get<double>();
    if (!std::isfinite(number)) fail("key \"" + path + "\" is not a finite number");
    return number;
  }

  float to_float(double value, const std::string& path) const {
    if (std::abs(value) > static_cast<double>(std::numeric_limits<float>::max())) {
      fail("key \"" + path + "\" (" + number_text(value) + ") is out of float32 range");
    }
    return static_cast<float>(value);
  }

  std::string where_;
};

json parse_sidecar(const std::filesystem::path& path) {
  const std::string where = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw InputError(where + ": missing capture sidecar (" + kSidecarName + " is not there)");
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(where + ": the capture sidecar is not a regular file");
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  std::string text(ec ? 0 : static_cast<std::size_t>(size), '\0');
  if (ec || !in || !in.read(text.data(), static_cast<std::streamsize>(text.size()))) {
    throw InputError(where + ": cannot read the capture sidecar");
  }
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throw InputError(where + ": the capture sidecar is not valid JSON: " + printable_text(e.what()));
  }
  if (!doc.is_object()) {
    throw InputError(where + ": the capture sidecar is not a JSON object (it is a " +
                     doc.type_name() + ")");
  }
  return doc;
}

// The camera and light descriptions, with the ranges the generators rely on.
void read_camera(const SidecarReader& reader, const json& doc, CaptureMeta& meta) {
  const json& camera = reader.object(doc, "", "camera");
  meta.camera.position = reader.vec3(camera, "camera", "position");
  meta.camera.target = reader.vec3(camera, "camera", "target");
  meta.camera.up = reader.vec3(camera, "camera", "up");
  meta.camera.fov_y_deg = reader.real32(camera, "camera", "fov_y_deg");
  meta.camera.near_plane = reader.real32(camera, "camera", "near");
  meta.camera.far_plane = reader.real32(camera, "camera", "far");
  meta.camera_view = reader.mat4(camera, "camera", "view");
  meta.camera_projection = reader.mat4(camera, "camera", "projection");
  if (!(meta.camera.fov_y_deg > 0.0f && meta.camera.fov_y_deg < 180.0f)) {
    reader.fail("key \"camera.fov_y_deg\" is " + number_text(meta.camera.fov_y_deg) +
                ", expected a value in (0, 180)");
  }
  if (!(meta.camera.near_plane > 0.0f && meta.camera.near_plane < meta.camera.far_plane)) {
    reader.fail("keys \"camera.near\" and \"camera.far\" must satisfy 0 < near < far");
  }
}

void read_light(const SidecarReader& reader, const json& doc, CaptureMeta& meta) {
  const json& light = reader.object(doc, "", "light");
  meta.light.position = reader.vec3(light, "light", "position");
  meta.light.direction = reader.vec3(light, "light", "direction");
  meta.light.up = reader.vec3(light, "light", "up");
  meta.light.cone_half_angle_deg = reader.real32(light, "light", "cone_half_angle_deg");
  meta.light.intensity = reader.vec3(light, "light", "intensity");
  meta.light.near_plane = reader.real32(light, "light", "near");
  meta.light.far_plane = reader.real32(light, "light", "far");
  meta.light_view = reader.mat4(light, "light", "view");
  meta.light_projection = reader.mat4(light, "light", "projection");
  const double direction_length = static_cast<double>(glm::length(meta.light.direction));
  if (std::abs(direction_length - 1.0) > kUnitNormalTolerance) {
    reader.fail("key \"light.direction\" is not a unit vector (length " +
                number_text(direction_length) + ")");
  }
  if (!(meta.light.cone_half_angle_deg > 0.0f && meta.light.cone_half_angle_deg < 90.0f)) {
    reader.fail("key \"light.cone_half_angle_deg\" is " +
                number_text(meta.light.cone_half_angle_deg) + ", expected a value in (0, 90)");
  }
  if (meta.light.intensity.r < 0.0f || meta.light.intensity.g < 0.0f ||
      meta.light.intensity.b < 0.0f) {
    reader.fail("key \"light.intensity\" has a negative component");
  }
  if (!(meta.light.near_plane > 0.0f && meta.light.near_plane < meta.light.far_plane)) {
    reader.fail("keys \"light.near\" and \"light.far\" must satisfy 0 < near < far");
  }
}

CaptureMeta read_meta(const SidecarReader& reader, const json& doc) {
  const std::string format = reader.string(doc, "", "format");
  if (format != kFormatName) {
    reader.fail("key \"format\" is " + quoted_text(format) + ", expected \"" + kFormatName + "\"");
  }
  const uint32_t version = reader.uint32(doc, "", "format_version");
  if (version != kFormatVersion) {
    reader.fail("unsupported format_version " + std::to_string(version) + " (this tool reads " +
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
    reader.fail("key \"scene\" is " + quoted_text(meta.scene) +
                ", expected a name of at most 64 letters, digits, '.', '_' or '-' (not starting with '.')");
  }
  meta.frame = reader.uint32(doc, "", "frame");
  meta.frames = reader.uint32(doc, "", "frames");
  if (meta.frames == 0 || meta.frame >= meta.frames) {
    reader.fail("key \"frame\" (" + std::to_string(meta.frame) + ") must be below \"frames\" (" +
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
      reader.fail("key \"units." + std::string(quantity) + "\" is " + quoted_text(found) + ", expected \"" +
                  unit + "\"");
    }
  }
  read_camera(reader, doc, meta);
  read_light(reader, doc, meta);
  meta.brsm_build_ms = reader.real(doc, "", "brsm_build_ms");
  if (meta.brsm_build_ms < 0.0) reader.fail("key \"brsm_build_ms\" is negative");
  return meta;
}

// What the sidecar says about one view.
struct ViewRecord {
  std::string file;
  uint32_t width = 0;
  uint32_t height = 0;
  bool has_pdf = true;
  std::array<std::string, kChannelCount> hashes;
};

ViewRecord read_view_record(const SidecarReader& reader, const json& doc, ViewKind kind) {
  const std::string label = view_label(kind);
  const json& section = reader.object(doc, "", view_label(kind));
  ViewRecord record;
  record.file = reader.string(section, label, "file");
  if (record.file != view_file_name(kind)) {
    reader.fail("key \"" + label + ".file\" is " + quoted_text(record.file) + ", expected \"" +
                view_file_name(kind) + "\"");
  }
  record.width = reader.uint32(section, label, "width");
  record.height = reader.uint32(section, label, "height");
  if (record.width == 0 || record.height == 0) {
    reader.fail("keys \"" + label + ".width\" and \"" + label + ".height\" must be positive");
  }
  if (record.width > kMaxViewSide || record.height > kMaxViewSide ||
      uint64_t{record.width} * record.height > kMaxViewTexels) {
    reader.fail("keys \"" + label + ".width\" and \"" + label + ".height\" say " +
                std::to_string(record.width) + "x" + std::to_string(record.height) +
                ", larger than a capture may be (at most " + std::to_string(kMaxViewSide) +
                " per side and " + std::to_string(kMaxViewTexels) + " texels)");
  }
  record.has_pdf = reader.boolean(section, label, "has_pdf");
  if (kind == ViewKind::kCamera && !record.has_pdf) {
    reader.fail("key \"gbuffer.has_pdf\" is false; the camera PDF is required");
  }
  const std::string pdf = reader.string(section, label, "pdf");
  const char* expected_pdf = kind == ViewKind::kCamera ? kCameraPdfName
                             : record.has_pdf          ? kRsmPdfName
                                                       : kNoPdfName;
  if (pdf != expected_pdf) {
    reader.fail("key \"" + label + ".pdf\" is " + quoted_text(pdf) + ", expected \"" + expected_pdf +
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
      reader.fail("key \"" + channels_path + "\" lists an unexpected channel " + quoted_text(item.key()));
    }
  }
  return record;
}

// ---- EXR loading and value checks ---------------------------------------------------------------

ViewImage read_view_file(const std::filesystem::path& path, ViewKind kind,
                         const ViewRecord& record) {
  const std::string where = path.string();
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
  const std::string where = path.string();
  ViewImage view = read_view_file(path, kind, record);
  check_finite(view, where);
  check_geometry(view, where);
  check_pdf(view, where);
  check_hashes(view, record, where);
  return view;
}

}  // namespace

std::span<const char* const> channel_names(ViewKind kind) {
  return kind == ViewKind::kCamera ? std::span<const char* const>(kCameraChannelNames)
                                   : std::span<const char* const>(kLightChannelNames);
}

const char* view_file_name(ViewKind kind) {
  return kind == ViewKind::kCamera ? "gbuffer.exr" : "rsm.exr";
}

const char* view_label(ViewKind kind) { return kind == ViewKind::kCamera ? "gbuffer" : "rsm"; }

void ViewImage::resize(ViewKind k, uint32_t w, uint32_t h) {
  kind = k;
  width = w;
  height = h;
  for (std::vector<float>& plane : planes) plane.assign(std::size_t{w} * h, 0.0f);
}

std::string plane_hash(const std::vector<float>& plane) {
  // The hash is defined over the little-endian bytes of the floats.
  static_assert(std::endian::native == std::endian::little);
  constexpr uint64_t kOffsetBasis = 14695981039346656037ull;
  constexpr uint64_t kPrime = 1099511628211ull;
  uint64_t hash = kOffsetBasis;
  const auto* bytes = reinterpret_cast<const unsigned char*>(plane.data());
  const std::size_t size = plane.size() * sizeof(float);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= bytes[i];
    hash *= kPrime;
  }
  char text[8 + 16 + 1];
  std::snprintf(text, sizeof text, "fnv1a64:%016llx", static_cast<unsigned long long>(hash));
  return text;
}

CaptureMeta write_capture(const Capture& capture, const std::filesystem::path& dir) {
  const std::filesystem::path gbuffer_path = dir / view_file_name(ViewKind::kCamera);
  const std::filesystem::path rsm_path = dir / view_file_name(ViewKind::kLight);
  const std::filesystem::path sidecar_path = dir / kSidecarName;
  check_view_for_writing(capture.gbuffer, ViewKind::kCamera, gbuffer_path.string());
  check_view_for_writing(capture.rsm, ViewKind::kLight, rsm_path.string());

  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw InputError(dir.string() + ": cannot create the capture directory: " +
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

  // The images first, the sidecar last: the sidecar's rename commits the capture.
  write_file_atomic(gbuffer_path, encode_view(capture.gbuffer, gbuffer_path.string()));
  write_file_atomic(rsm_path, encode_view(capture.rsm, rsm_path.string()));
  std::string sidecar;
  try {
    sidecar = sidecar_text(meta, capture);
  } catch (const json::exception& e) {  // e.g. a scene or device name that is not UTF-8
    throw InputError(sidecar_path.string() + ": cannot write the capture sidecar: " + e.what());
  }
  write_text_atomic(sidecar_path, sidecar);
  return meta;
}

Capture load_capture(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::exists(dir, ec)) {
    throw InputError(dir.string() + ": capture directory does not exist");
  }
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(dir.string() + ": not a directory; a capture is a directory");
  }
  const std::filesystem::path sidecar_path = dir / kSidecarName;
  const json doc = parse_sidecar(sidecar_path);
  const SidecarReader reader(sidecar_path.string());
  Capture capture;
  capture.meta = read_meta(reader, doc);
  const ViewRecord gbuffer_record = read_view_record(reader, doc, ViewKind::kCamera);
  const ViewRecord rsm_record = read_view_record(reader, doc, ViewKind::kLight);
  capture.gbuffer = load_view(dir, ViewKind::kCamera, gbuffer_record);
  capture.rsm = load_view(dir, ViewKind::kLight, rsm_record);
  capture.meta.gbuffer_hashes = gbuffer_record.hashes;
  capture.meta.rsm_hashes = rsm_record.hashes;
  return capture;
}

}  // namespace vsgl
