// Which scene a run timed (formats/scene_identity.hpp): read and written by the table model
// (schema 3's object, schema 1-2's plain name), derived from a capture's sidecar, and kept apart
// by compare (refused, whatever the flags), export (names) and the dashboard (series, headings).
#include <gtest/gtest.h>

#include <string>

#include "harness/compare/dashboard_page.hpp"
#include "harness/compare/export_formats.hpp"
#include "harness/compare/regression_compare.hpp"
#include "harness/compare/regression_run.hpp"
#include "harness/core/error.hpp"
#include "harness/formats/scene_identity.hpp"
#include "harness/formats/table_model.hpp"
#include "harness/report/capture_scene_identity.hpp"
#include "synthetic_header.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

SceneIdentity paper_sponza() {
  SceneIdentity s;
  s.name = "sponza";
  s.kind = SceneKind::kPaper;
  s.preset = "sponza";
  s.model_file = "Sponza.gltf";
  s.content_hash = "fnv1a64:00000000000000aa";
  s.triangles = 262267;
  return s;
}

SceneIdentity stand_in_atrium() {
  SceneIdentity s;
  s.name = "atrium";
  s.kind = SceneKind::kStandIn;
  return s;
}

std::string document_error(const ojson& doc) {
  try {
    scene_identity_from_json(doc, "t.json", "/scene");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneIdentity, ObjectRoundTripsForEveryKind) {
  SceneIdentity user = paper_sponza();
  user.kind = SceneKind::kUser;
  user.preset.clear();
  SceneIdentity tiny;
  tiny.name = "tiny";
  for (const SceneIdentity& s : {paper_sponza(), stand_in_atrium(), user, tiny}) {
    const ojson j = to_json(s);
    ASSERT_TRUE(j.is_object());
    EXPECT_EQ(j["kind"], scene_kind_name(s.kind));
    const SceneIdentity back = scene_identity_from_json(j, "t.json", "/scene");
    EXPECT_EQ(to_json(back).dump(), j.dump());
    EXPECT_TRUE(scene_difference(s, back).empty());
  }
  EXPECT_FALSE(to_json(stand_in_atrium()).contains("model_file"));
  EXPECT_EQ(to_json(paper_sponza())["content_hash"], "fnv1a64:00000000000000aa");
}

TEST(SceneIdentity, RefusesWhatIsNotAScene) {
  const ojson good = to_json(paper_sponza());
  ojson kind = good;
  kind["kind"] = "paper-ish";
  EXPECT_NE(document_error(kind).find("/scene/kind"), std::string::npos) << document_error(kind);
  ojson extra = good;
  extra["colour"] = "red";
  EXPECT_NE(document_error(extra).find("colour"), std::string::npos) << document_error(extra);
  ojson no_model = good;
  no_model.erase("model_file");
  EXPECT_NE(document_error(no_model).find("without its model_file"), std::string::npos) << document_error(no_model);
  ojson procedural_model = to_json(stand_in_atrium());
  procedural_model["model_file"] = "a.obj";
  procedural_model["content_hash"] = "fnv1a64:0000000000000001";
  procedural_model["triangles"] = 2;
  EXPECT_NE(document_error(procedural_model).find("procedural scenes have none"), std::string::npos);
  ojson no_hash = good;
  no_hash.erase("content_hash");
  EXPECT_NE(document_error(no_hash).find("content_hash"), std::string::npos) << document_error(no_hash);
  EXPECT_NE(document_error(ojson("sponza")).find("an object"), std::string::npos);
}

TEST(SceneIdentity, DifferencesNameBothScenesOrTheirModels) {
  EXPECT_NE(
      scene_difference(paper_sponza(), stand_in_atrium()).find("'sponza, paper scene' is not scene 'atrium, stand-in'"),
      std::string::npos);
  SceneIdentity other_model = paper_sponza();
  other_model.content_hash = "fnv1a64:00000000000000bb";
  EXPECT_NE(scene_difference(paper_sponza(), other_model).find("different models"), std::string::npos);
  SceneIdentity same_name_other_kind = stand_in_atrium();
  same_name_other_kind.kind = SceneKind::kProcedural;
  EXPECT_FALSE(scene_difference(stand_in_atrium(), same_name_other_kind).empty());
}

TEST(SceneIdentity, FollowsFromTheCaptureSidecar) {
  CaptureMeta meta;
  meta.scene = "atrium";
  EXPECT_EQ(capture_scene_identity(meta).kind, SceneKind::kStandIn);
  meta.scene = "tiny";
  EXPECT_EQ(capture_scene_identity(meta).kind, SceneKind::kProcedural);
  meta.scene = "sponza";
  meta.source = SceneSource{"gltf", "Sponza.gltf", "fnv1a64:00000000000000aa", 262267, "preset", "preset", "sponza", 1};
  const SceneIdentity paper = capture_scene_identity(meta);
  EXPECT_EQ(paper.kind, SceneKind::kPaper);
  EXPECT_EQ(paper.preset, "sponza");
  EXPECT_EQ(paper.triangles, 262267u);
  // A preset of no paper table (sibenik, Fig. 5 only) is still the paper's scene, not a user's.
  meta.scene = "sibenik";
  meta.source->preset = "sibenik";
  meta.source->paper_table = 0;
  EXPECT_EQ(capture_scene_identity(meta).kind, SceneKind::kPaper);
  EXPECT_EQ(capture_scene_identity(meta).preset, "sibenik");
  // A file given directly, named like a paper scene, is the user's.
  meta.source->preset.clear();
  meta.source->paper_table = 0;
  EXPECT_EQ(capture_scene_identity(meta).kind, SceneKind::kUser);
}

// The smallest table document the model reads, at a schema version, with a scene.
ojson table_doc(int version, const ojson& scene) {
  const ojson stats{{"median_ms", 1.0}, {"paper_ms", nullptr}, {"q1_ms", 1.0}, {"q3_ms", 1.0}, {"samples_ms", {1.0}}};
  ojson views = ojson::object();
  for (const char* v : {"camera_view", "light_view"})
    views[v] = ojson{{"phases", ojson{{"additional", stats}}}, {"total", stats}};
  return ojson{{"schema_version", version},
               {"table", 1},
               {"scene", scene},
               {"generators", ojson{{"fis_tok15", ojson{{"views", views}, {"total", stats}}}}}};
}

TEST(SceneIdentity, TableSchemaTwoNamesAreInferredAndWrittenBackAsNames) {
  const TableModel v2 = table_model_from_json(table_doc(2, "atrium"), "v2.json");
  ASSERT_TRUE(v2.scene);
  EXPECT_TRUE(v2.scene->name_only);
  EXPECT_EQ(v2.scene->kind, SceneKind::kStandIn);  // a paper table without a model: the stand-in
  EXPECT_EQ(to_json(v2)["scene"], "atrium");
  const TableModel v3 = table_model_from_json(table_doc(3, to_json(paper_sponza())), "v3.json");
  ASSERT_TRUE(v3.scene);
  EXPECT_EQ(v3.scene->kind, SceneKind::kPaper);
  EXPECT_EQ(to_json(v3)["scene"].dump(), to_json(paper_sponza()).dump());
  try {
    table_model_from_json(table_doc(3, "atrium"), "v3.json");
    FAIL() << "a schema 3 table with a plain scene name was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/scene"), std::string::npos) << e.what();
  }
}

TEST(SceneIdentity, SchemaOneTablesAreLabelledByTheirCaptureScene) {
  ojson doc = table_doc(1, "unused");
  doc.erase("scene");  // schema 1 named the scene only under /capture
  doc["device"] = to_json(test::synthetic_device("GPU", "discrete"));
  doc["build"] = to_json(test::synthetic_build("abc1234"));
  doc["run"] = to_json(test::synthetic_run("2026-11-22T00:00:00Z"));
  doc["config"] = ojson{{"K", 1}};
  doc["capture"] = ojson{{"scene", "atrium"}, {"hashes", ojson{{"gbuffer", ojson::object()}}}};
  const BenchRun run = parse_bench_run(doc, "h100/table1.json");
  ASSERT_TRUE(run.tables.at(1).scene);
  EXPECT_EQ(scene_label(*run.tables.at(1).scene), "atrium, stand-in");
}

BenchRun run_on(const SceneIdentity& scene, const std::string& device, const std::string& date) {
  BenchRun r;
  r.path = device + "/" + scene.name + "/table1.json";
  r.format = "table";
  r.device = device;
  r.git_commit = "abc1234";
  r.date = date;
  RunTable t;
  t.table = 1;
  t.capture_hashes = nlohmann::ordered_json{{"gbuffer", "h"}};
  t.workload = nlohmann::ordered_json{{"K", 1}};
  t.scene = scene;
  r.tables[1] = t;
  for (const char* name : {"table1/fis_tok15/total", "table1/fis_tok15/camera_view/additional"}) {
    RunSeries s;
    s.name = name;
    s.table = 1;
    s.generator = "fis_tok15";
    s.view = std::string(name).find("camera_view") != std::string::npos ? "camera_view" : "";
    s.phase = s.view.empty() ? "total" : "additional";
    s.samples_ms = {1.0, 1.1, 0.9, 1.0, 1.05, 0.95};
    s.median_ms = 1.0, s.q1_ms = 0.95, s.q3_ms = 1.05;
    r.series.push_back(s);
  }
  return r;
}

TEST(SceneIdentity, CompareRefusesAStandInAgainstThePaperSceneEvenWhenMismatchesAreAllowed) {
  const BenchRun paper = run_on(paper_sponza(), "GPU", "2026-12-01T00:00:00Z");
  const BenchRun stand_in = run_on(stand_in_atrium(), "GPU", "2026-12-02T00:00:00Z");
  for (const bool allow : {false, true}) {
    CompareOptions o;
    o.allow_mismatch = allow;
    try {
      compare_runs(stand_in, paper, o);
      FAIL() << "a stand-in run was compared with a paper-scene run";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("atrium, stand-in"), std::string::npos) << m;
      EXPECT_NE(m.find("sponza, paper scene"), std::string::npos) << m;
      EXPECT_NE(m.find("--allow-mismatch does not apply"), std::string::npos) << m;
    }
  }
  EXPECT_NO_THROW(compare_runs(paper, paper, {}));
}

TEST(SceneIdentity, ExportNamesCarryTheScene) {
  const BenchRun paper = run_on(paper_sponza(), "GPU", "2026-12-01T00:00:00Z");
  const ojson gab = export_run(paper, ExportFormat::kGithubActionBenchmark);
  ASSERT_FALSE(gab.empty());
  EXPECT_EQ(gab[0]["name"], "table1/fis_tok15/total [sponza, paper scene]");
  const ojson bmf =
      export_run(run_on(stand_in_atrium(), "GPU", "2026-12-01T00:00:00Z"), ExportFormat::kBencherMetricFormat);
  EXPECT_TRUE(bmf.contains("table1/fis_tok15/total [atrium, stand-in]")) << bmf.dump();
}

TEST(SceneIdentity, DashboardKeepsOneSeriesPerDeviceAndScene) {
  const std::vector<BenchRun> runs{run_on(stand_in_atrium(), "GPU", "2026-12-01T00:00:00Z"),
                                   run_on(paper_sponza(), "GPU", "2026-12-02T00:00:00Z")};
  const std::string html = dashboard_html(runs, nlohmann::ordered_json::object(), "results", {});
  EXPECT_NE(html.find("Table 1 (atrium, stand-in; sponza, paper scene)"), std::string::npos);
  EXPECT_NE(html.find("GPU (atrium, stand-in)"), std::string::npos);
  EXPECT_NE(html.find("GPU (sponza, paper scene)"), std::string::npos);
  EXPECT_NE(html.find("<td>sponza, paper scene</td>"), std::string::npos);
}

}  // namespace
}  // namespace vsgl
