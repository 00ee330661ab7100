#include "harness/scene/scene_preset.hpp"

#include <algorithm>
#include <cmath>

#include "harness/core/path_text.hpp"
#include "harness/core/embedded_files.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/core/text_file.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;

constexpr const char* kBuiltInPresetDir = "harness/scene/presets/";

glm::vec3 read_vec3(const JsonReader& r, const json& object, const std::string& parent, const char* key) {
  const json& a = r.array(object, parent, key, 3);
  const std::string path = r.child(parent, key);
  return glm::vec3(r.number32(a[0], r.element(path, 0)), r.number32(a[1], r.element(path, 1)),
                   r.number32(a[2], r.element(path, 2)));
}

float read_in_range(const JsonReader& r, const json& object, const std::string& parent, const char* key, float lo,
                    float hi) {
  const float v = r.number32(r.member(object, parent, key), r.child(parent, key));
  if (!(v > lo && v < hi))
    r.fail(r.child(parent, key), "is " + std::to_string(v) + ", expected a value in (" + std::to_string(lo) + ", " +
                                     std::to_string(hi) + ")");
  return v;
}

uint32_t read_positive(const JsonReader& r, const json& value, const std::string& path) {
  if (!value.is_number_unsigned() || value.get<uint64_t>() == 0 || value.get<uint64_t>() > 16384)
    r.fail(path, "must be a whole number in [1, 16384]");
  return value.get<uint32_t>();
}

void read_model(const JsonReader& r, const json& doc, ScenePreset& p) {
  const json& model = r.member(doc, "", "model");
  if (!model.is_array() || model.empty()) r.wrong_type(model, "model", "a non-empty array of relative paths");
  for (std::size_t i = 0; i < model.size(); ++i) {
    const std::string path = r.element("model", i);
    if (!model[i].is_string()) r.wrong_type(model[i], path, "a string");
    const std::filesystem::path rel(model[i].get<std::string>());
    const bool climbs = std::any_of(rel.begin(), rel.end(), [](const auto& part) { return part == ".."; });
    if (rel.empty() || rel.is_absolute() || climbs)
      r.fail(path, "must be a path relative to an asset directory, without \"..\"");
    p.model.push_back(rel.generic_string());
  }
}

void read_camera(const JsonReader& r, const json& doc, ScenePreset& p) {
  const json& c = r.object(doc, "", "camera");
  r.only_keys(c, "camera", {"eye", "look_at", "fov_y_deg"});
  p.camera.eye = read_vec3(r, c, "camera", "eye");
  p.camera.look_at = read_vec3(r, c, "camera", "look_at");
  if (*p.camera.eye == *p.camera.look_at) r.fail("camera.look_at", "equals camera.eye");
  p.camera.fov_y_deg = read_in_range(r, c, "camera", "fov_y_deg", 0.0f, 179.0f);
}

void read_light(const JsonReader& r, const json& doc, ScenePreset& p) {
  const json& l = r.object(doc, "", "light");
  r.only_keys(l, "light", {"position", "direction", "cone_half_angle_deg", "intensity_w_per_sr"});
  p.light.position = read_vec3(r, l, "light", "position");
  p.light.direction = read_vec3(r, l, "light", "direction");
  if (glm::length(*p.light.direction) == 0.0f) r.fail("light.direction", "is zero");
  p.light.cone_half_angle_deg = read_in_range(r, l, "light", "cone_half_angle_deg", 0.0f, 90.0f);
  const float intensity = r.number32(r.member(l, "light", "intensity_w_per_sr"), "light.intensity_w_per_sr");
  if (intensity < 0.0f) r.fail("light.intensity_w_per_sr", "is negative");
  p.light.intensity = glm::vec3(intensity);
}

void read_sizes(const JsonReader& r, const json& doc, ScenePreset& p) {
  const json& s = r.object(doc, "", "sizes");
  r.only_keys(s, "sizes", {"gbuffer", "rsm"});
  const json& g = r.member(s, "sizes", "gbuffer");
  if (!g.is_array() || g.size() != 2) r.wrong_type(g, "sizes.gbuffer", "an array [width, height]");
  p.sizes.gbuffer_width = read_positive(r, g[0], "sizes.gbuffer[0]");
  p.sizes.gbuffer_height = read_positive(r, g[1], "sizes.gbuffer[1]");
  p.sizes.rsm_size = read_positive(r, r.member(s, "sizes", "rsm"), "sizes.rsm");
}

void read_motion(const JsonReader& r, const json& doc, ScenePreset& p) {
  const json& m = r.object(doc, "", "motion");
  r.only_keys(m, "motion", {"light_circle_m", "aim_wobble_deg", "camera_dolly_m"});
  const auto non_negative = [&](const char* key) {
    const float v = r.number32(r.member(m, "motion", key), r.child("motion", key));
    if (v < 0.0f) r.fail(r.child("motion", key), "is negative");
    return v;
  };
  p.motion.light_circle_m = non_negative("light_circle_m");
  p.motion.aim_wobble_deg = non_negative("aim_wobble_deg");
  p.motion.camera_dolly_m = non_negative("camera_dolly_m");
}

}  // namespace

ScenePreset parse_scene_preset(const ScenePresetFile& file) {
  const std::string origin = printable_text(file.origin, std::string_view::npos);
  const json doc = parse_json_text(file.text, origin, "the scene preset");
  const JsonReader r("scene preset " + origin, JsonPathStyle::kDottedKey);
  if (!doc.is_object()) r.wrong_type(doc, "", "an object");
  r.only_keys(doc, "",
              {"name", "description", "paper_table", "model", "where_to_get", "camera", "light", "sizes", "motion"});
  ScenePreset p;
  p.origin = file.origin;
  p.name = r.string(doc, "", "name");
  if (p.name != file.name)
    r.fail("name", "is " + quoted_text(p.name) + ", expected the file's stem " + quoted_text(file.name));
  p.description = r.string(doc, "", "description");
  p.paper_table = r.uint32(doc, "", "paper_table");
  if (p.paper_table > 2) r.fail("paper_table", "is " + std::to_string(p.paper_table) + ", expected 0, 1 or 2");
  read_model(r, doc, p);
  p.where_to_get = r.string(doc, "", "where_to_get");
  read_camera(r, doc, p);
  read_light(r, doc, p);
  read_sizes(r, doc, p);
  read_motion(r, doc, p);
  return p;
}

ScenePreset read_scene_preset(const std::filesystem::path& file) {
  return parse_scene_preset(
      ScenePresetFile{file.stem().string(), path_text(file), read_text_file(file, "the scene preset")});
}

std::vector<ScenePresetFile> built_in_scene_presets() {
  std::vector<ScenePresetFile> out;
  for (const std::string& name : embedded_file_names(kBuiltInPresetDir)) {
    const std::filesystem::path rel(name);
    if (rel.extension() != ".json" || rel.parent_path() != std::filesystem::path(kBuiltInPresetDir).parent_path())
      continue;
    out.push_back({rel.stem().string(), embedded_file_label(name), std::string(*embedded_file(name))});
  }
  return out;  // embedded_file_names() is sorted, and so are the stems of one directory's files
}

std::vector<ScenePresetFile> scene_preset_files(const std::filesystem::path& dir) {
  std::vector<ScenePresetFile> out;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".json")
      out.push_back({e.path().stem().string(), path_text(e.path()), read_text_file(e.path(), "the scene preset")});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

std::vector<std::string> scene_preset_names(const std::vector<ScenePresetFile>& presets) {
  std::vector<std::string> names;
  for (const ScenePresetFile& p : presets) names.push_back(p.name);
  return names;
}

ScenePreset find_scene_preset(const std::vector<ScenePresetFile>& presets, const std::string& name) {
  const auto it =
      std::find_if(presets.begin(), presets.end(), [&](const ScenePresetFile& p) { return p.name == name; });
  if (it == presets.end()) {
    std::string known;
    for (const auto& n : scene_names()) known += (known.empty() ? "" : ", ") + n;
    std::string names;
    for (const auto& p : presets) names += (names.empty() ? "" : ", ") + p.name;
    throw InputError("no scene named " + quoted_text(name) + ": the procedural scenes are " + known +
                     ", and the scene presets are " + (names.empty() ? "none" : names));
  }
  return parse_scene_preset(*it);
}

}  // namespace vsgl
