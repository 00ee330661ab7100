#pragma once
// Which scene a run timed, as every result names it (DESIGN.md §3.4): the tables' JSON carries it,
// and `compare`, `dashboard` and `export` use it so a run on a procedural stand-in is never set
// against a run on the paper's own scene of the same table.
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace vsgl {

enum class SceneKind {
  kPaper,       // a preset of the paper's scenes (sponza, conference-room, sibenik) from its real model
  kStandIn,     // a procedural scene timed in place of a paper table's scene (atrium, conference)
  kProcedural,  // any other procedural scene (the tiny test scene)
  kUser,        // a model file given directly (record --model)
};

struct SceneIdentity {
  std::string name;  // the capture's scene: a preset's or procedural scene's name, a file's stem
  SceneKind kind = SceneKind::kProcedural;
  std::string preset;        // the preset recorded through; empty for none
  std::string model_file;    // the model file as named when recorded; empty for procedural scenes
  std::string content_hash;  // "fnv1a64:<16 hex>" over the model and what it references; empty: procedural
  uint64_t triangles = 0;    // of the model; 0 for procedural scenes
  // Read from a file of table schema 1 or 2, which named the scene only: the kind is inferred
  // (stand-in for a paper table, user for a file's capture, else procedural) and the identity is
  // written back as that name, so such a file round-trips unchanged.
  bool name_only = false;
};

const char* scene_kind_name(SceneKind kind);  // "paper", "stand-in", "procedural", "user"
std::optional<SceneKind> scene_kind_from_name(std::string_view name);

// "sponza, paper scene" / "atrium, stand-in": how reports and the dashboard label a run.
std::string scene_label(const SceneIdentity& scene);

// Why two runs' scenes are not the same scene, in words; empty when they are (same name, kind and
// model hash). Two runs of different scenes time different inputs, whatever else they share.
std::string scene_difference(const SceneIdentity& a, const SceneIdentity& b);

// Table schema 3's `scene` object (a name_only identity: its plain name, as schema 1-2 wrote it).
nlohmann::ordered_json to_json(const SceneIdentity& scene);
// Reads the object at `pointer` of the document `what` names; refuses unknown keys and kinds, and a
// paper or user scene without its model. Throws InputError.
SceneIdentity scene_identity_from_json(const nlohmann::ordered_json& object, const std::string& what,
                                       const std::string& pointer);

}  // namespace vsgl
