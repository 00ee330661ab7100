#include "harness/report/capture_scene_identity.hpp"

#include "harness/report/tables_run.hpp"

namespace vsgl {

SceneIdentity capture_scene_identity(const CaptureMeta& meta) {
  SceneIdentity s;
  s.name = meta.scene;
  if (meta.source) {
    const SceneSource& src = *meta.source;
    s.kind = !src.preset.empty() ? SceneKind::kPaper : SceneKind::kUser;
    s.preset = src.preset;
    s.model_file = src.file;
    s.content_hash = src.content_hash;
    s.triangles = src.triangles;
  } else {
    s.kind = paper_table_of(meta) != 0 ? SceneKind::kStandIn : SceneKind::kProcedural;
  }
  return s;
}

}  // namespace vsgl
