#include "harness/formats/scene_identity.hpp"

#include "harness/core/json_reader.hpp"
#include "harness/core/printable_text.hpp"

namespace vsgl {

const char* scene_kind_name(SceneKind kind) {
  switch (kind) {
    case SceneKind::kPaper: return "paper";
    case SceneKind::kStandIn: return "stand-in";
    case SceneKind::kProcedural: return "procedural";
    case SceneKind::kUser: return "user";
  }
  return "?";
}

std::optional<SceneKind> scene_kind_from_name(std::string_view name) {
  for (SceneKind k : {SceneKind::kPaper, SceneKind::kStandIn, SceneKind::kProcedural, SceneKind::kUser})
    if (name == scene_kind_name(k)) return k;
  return std::nullopt;
}

std::string scene_label(const SceneIdentity& scene) {
  switch (scene.kind) {
    case SceneKind::kPaper: return scene.name + ", paper scene";
    case SceneKind::kStandIn: return scene.name + ", stand-in";
    case SceneKind::kProcedural: return scene.name + ", procedural";
    case SceneKind::kUser: return scene.name + ", user's model";
  }
  return scene.name;
}

std::string scene_difference(const SceneIdentity& a, const SceneIdentity& b) {
  const auto quoted = [](const SceneIdentity& s) { return "'" + scene_label(s) + "'"; };
  if (a.name != b.name || a.kind != b.kind) return "scene " + quoted(a) + " is not scene " + quoted(b);
  if (a.content_hash != b.content_hash)
    return "scene " + quoted(a) + " was recorded from different models (" +
           (a.content_hash.empty() ? "none" : a.content_hash) + " vs " +
           (b.content_hash.empty() ? "none" : b.content_hash) + ")";
  return {};
}

nlohmann::ordered_json to_json(const SceneIdentity& s) {
  if (s.name_only) return s.name;
  nlohmann::ordered_json o{{"name", s.name}, {"kind", scene_kind_name(s.kind)}};
  if (!s.preset.empty()) o["preset"] = s.preset;
  if (!s.model_file.empty()) {
    o["model_file"] = s.model_file;
    o["content_hash"] = s.content_hash;
    o["triangles"] = s.triangles;
  }
  return o;
}

SceneIdentity scene_identity_from_json(const nlohmann::ordered_json& o, const std::string& what, const std::string& p) {
  const JsonReader r(what, JsonPathStyle::kPointer);
  if (!o.is_object()) r.wrong_type(o, p, "an object");
  r.only_keys(o, p, {"name", "kind", "preset", "model_file", "content_hash", "triangles"});
  SceneIdentity s;
  s.name = r.string(o, p, "name");
  const std::string kind = r.string(o, p, "kind");
  const auto k = scene_kind_from_name(kind);
  if (!k) r.fail(p + "/kind", "is '" + printable_text(kind) + "', not paper, stand-in, procedural or user");
  s.kind = *k;
  if (o.contains("preset")) s.preset = r.string(o, p, "preset");
  if (o.contains("model_file")) {
    s.model_file = r.string(o, p, "model_file");
    s.content_hash = r.string(o, p, "content_hash");
    const nlohmann::ordered_json& t = r.member(o, p, "triangles");
    if (!t.is_number_unsigned() && !(t.is_number_integer() && t.get<int64_t>() > 0))
      r.wrong_type(t, p + "/triangles", "a positive integer");
    s.triangles = t.get<uint64_t>();
  }
  if ((s.kind == SceneKind::kPaper || s.kind == SceneKind::kUser) && s.model_file.empty())
    r.fail(p, "is a " + kind + " scene without its model_file and content_hash");
  if ((s.kind == SceneKind::kStandIn || s.kind == SceneKind::kProcedural) && !s.model_file.empty())
    r.fail(p, "is a " + kind + " scene with a model_file: procedural scenes have none");
  return s;
}

}  // namespace vsgl
