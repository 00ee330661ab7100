// `tables` end to end on tiny captures (harness/report/tables_run.hpp): missing captures are recorded,
// every generator is timed on both views, and the JSON is complete, finite and conforms to
// results/schema/table.schema.json; a capture whose hash does not match its sidecar is refused.
// Also the schema validator itself and the line counter on hand-made inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>

#include "gpu_test.hpp"
#include "test_support.hpp"
#include "harness/compare/dashboard_page.hpp"
#include "harness/compare/regression_run.hpp"
#include "harness/core/error.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/core/source_lines.hpp"
#include "harness/report/tables_run.hpp"
#include "harness/scene/asset_search.hpp"
#include "harness/scene/capture_provisioning.hpp"
#include "harness/scene/scene_preset.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

using test::read_json;
using test::TempDir;

const fs::path kTableSchema = fs::path(VSGL_SOURCE_DIR) / "results/schema/table.schema.json";

TablesOptions tiny_options(const fs::path& root) {
  TablesOptions o;
  o.captures_dir = root / "captures";
  o.out_dir = root / "out";
  o.record_sizes = RecordSizes{96, 64, 64};
  o.camera_vsgls = 48;
  o.light_vsgls = 24;
  o.generators = {"fis_tok15", "fis_modified", "kmeans_2d", "kmeans_3d"};
  o.quick = true;
  o.timing.min_repetitions = 3;
  o.timing.max_repetitions = 3;
  o.copy_bandwidth.bytes = 1u << 20;  // the measurement's shape, not DESIGN.md §9's 256 MiB
  o.copy_bandwidth.copies = 3;
  return o;
}

class TablesRunTest : public test::GpuTest {};

TEST_F(TablesRunTest, TinyRunProducesCompleteFiniteTablesThatMatchTheSchema) {
  const TempDir temp("tables_complete");
  const fs::path& root = temp.path();
  TablesOptions o = tiny_options(root);
  o.scenes = SceneLibrary{built_in_scene_presets(), AssetSearch{{{root / "no-models", "--assets"}}}};
  std::vector<std::string> messages;
  const TablesOutcome out = run_tables(device(), o, [&](const TablesEvent& e) {
    if (e.progress == nullptr) messages.push_back(e.message);
  });
  ASSERT_EQ(out.documents.size(), 2u);
  // Without the paper's models it warns first, once per table, before recording or timing anything.
  ASSERT_GE(messages.size(), 3u);
  for (const int table : {1, 2}) {
    const std::string& m = messages[static_cast<std::size_t>(table - 1)];
    EXPECT_EQ(m.rfind("warning: table " + std::to_string(table) + ": the paper's scene", 0), 0u) << m;
    EXPECT_NE(m.find(kPaperScenesSection), std::string::npos) << m;
  }
  EXPECT_EQ(std::count_if(messages.begin(), messages.end(),
                          [](const std::string& m) { return m.find("the paper's scene") != std::string::npos; }),
            2);
  EXPECT_TRUE(fs::exists(root / "captures/atrium/capture.json"));  // recorded because missing
  EXPECT_TRUE(fs::exists(root / "captures/conference/capture.json"));
  const nlohmann::ordered_json schema = read_json(kTableSchema);
  for (int table : {1, 2}) {
    SCOPED_TRACE("table " + std::to_string(table));
    const fs::path json_path = root / "out" / ("table" + std::to_string(table) + ".json");
    ASSERT_TRUE(fs::exists(json_path));
    ASSERT_TRUE(fs::exists(root / "out" / ("table" + std::to_string(table) + ".md")));
    const std::string text = [&] {
      std::ifstream in(json_path);
      return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    EXPECT_EQ(text.find("NaN"), std::string::npos);
    const nlohmann::ordered_json doc = nlohmann::ordered_json::parse(text);
    const auto problems = validate_against_schema(doc, schema);
    EXPECT_TRUE(problems.empty()) << problems.front();
    EXPECT_EQ(doc["table"], table);
    // Without the paper's models the procedural scenes stand in, and the JSON says so.
    EXPECT_EQ(doc["scene"]["name"], table == 1 ? "atrium" : "conference");
    EXPECT_EQ(doc["scene"]["kind"], "stand-in");
    EXPECT_FALSE(doc["scene"].contains("model_file"));
    EXPECT_EQ(doc["timing"]["repetitions"], 3);
    for (const auto& g : o.generators) {
      SCOPED_TRACE(g);
      ASSERT_TRUE(doc["generators"].contains(g));
      for (const char* view : {"camera_view", "light_view"}) {
        const auto& v = doc["generators"][g]["views"][view];
        EXPECT_EQ(v["phases"].size(), 3u);
        for (const auto& [phase, st] : v["phases"].items()) {
          EXPECT_EQ(st["samples_ms"].size(), 3u) << phase;
          EXPECT_LE(st["min_ms"].get<double>(), st["median_ms"].get<double>());
          EXPECT_LE(st["median_ms"].get<double>(), st["max_ms"].get<double>());
          EXPECT_TRUE(st["paper_ms"].is_number()) << "the paper's value beside " << g << " " << view << " " << phase;
        }
        EXPECT_EQ(v["dispatch_calls"], doc["table3"][g]["dispatch_calls"][view]);
        // k-means: iterations x per iteration + the rest = the dispatches of the view.
        const auto& calls = doc["table3"][g]["dispatch_calls"];
        EXPECT_EQ(calls.contains("iterations"), g.rfind("kmeans", 0) == 0);
        if (calls.contains("iterations")) {
          const auto& it = calls["iterations"][view];
          EXPECT_EQ(it["iterations"].get<int>() * it["per_iteration"].get<int>() + it["outside"].get<int>(),
                    calls[view].get<int>());
        }
      }
      EXPECT_TRUE(doc["generators"][g]["total"]["paper_ms"].is_number());
      const auto& loc = doc["table3"][g]["lines_of_code"];
      EXPECT_GT(loc["measured"].get<int>(), 0);
      EXPECT_EQ(loc["shader_lines"].get<int>() + loc["host_lines"].get<int>(), loc["measured"].get<int>());
    }
    // Table 3's counting rule and the lines in which the FIS variants differ (the paper: 10).
    ASSERT_TRUE(doc.contains("table3_counting"));
    EXPECT_FALSE(doc["table3_counting"]["rule"].get<std::string>().empty());
    const auto& diff = doc["table3_counting"]["difference"];
    EXPECT_GT(diff["differing"].get<int>(), 0);
    EXPECT_EQ(diff["net"].get<int>(), doc["table3"]["fis_modified"]["lines_of_code"]["measured"].get<int>() -
                                          doc["table3"]["fis_tok15"]["lines_of_code"]["measured"].get<int>());
    EXPECT_EQ(diff["paper"], 10);
    // Both tables ran: every ratio the paper argues with is present.
    EXPECT_TRUE(doc["ratios"].contains("modified_minus_tok15_us"));
    EXPECT_TRUE(doc["ratios"]["kmeans_over_modified"].contains("kmeans_3d"));
    EXPECT_TRUE(doc["ratios"]["table1_to_table2"].contains("fis_modified"));
    EXPECT_EQ(doc["claims"].size(), 6u);
    // Three rounds cannot give a 95 % interval of the paired overhead: no verdict from them.
    EXPECT_EQ(doc["claims"][0]["id"], "modified_overhead");
    EXPECT_TRUE(doc["claims"][0]["holds"].is_null());
    EXPECT_EQ(doc["claims"][0]["note"].get<std::string>().rfind("inconclusive", 0), 0u);
    const auto& paired = doc["ratios"]["paired_modified_minus_tok15"];
    for (const char* view : {"camera_view", "light_view"})
      for (const char* what : {"total", "filtered_sampling"}) {
        const auto& d = paired[view][what];
        EXPECT_EQ(d["rounds"], 3);
        EXPECT_LE(d["ci_low_us"].get<double>(), d["hodges_lehmann_us"].get<double>());
        EXPECT_LE(d["hodges_lehmann_us"].get<double>(), d["ci_high_us"].get<double>());
        EXPECT_FALSE(d["reaches_nominal"].get<bool>());
      }
    // The physical limit: a copy bandwidth of this run and each streaming pass's fraction of it.
    const auto& copy = doc["bandwidth"]["copy"];
    EXPECT_EQ(copy["buffer_bytes"], 1u << 20);
    const double copy_bps = copy["bytes_per_s"].get<double>();
    EXPECT_TRUE(std::isfinite(copy_bps) && copy_bps > 0.0);
    for (const char* g : {"fis_tok15", "fis_modified"})
      for (const char* view : {"camera_view", "light_view"})
        for (const char* pass : {"additional", "mipmapping"}) {
          const auto& v = doc["bandwidth"]["passes"][g][view][pass];
          EXPECT_DOUBLE_EQ(v["fraction_of_copy"].get<double>(), v["achieved_bytes_per_s"].get<double>() / copy_bps)
              << g << " " << view << " " << pass;
        }
    EXPECT_FALSE(doc["bandwidth"]["passes"].contains("kmeans_2d"));  // no streaming pass to bound
    EXPECT_EQ(doc["capture"]["hashes"]["gbuffer"].size(), 15u);
    // DESIGN.md §6.1a: the texture path by default, with its format, sampler and precision limits.
    const auto& pyramid = doc["config"]["pyramid"];
    EXPECT_EQ(pyramid["path"], "texture");
    EXPECT_EQ(pyramid["image_format"], "R32G32B32A32_SFLOAT");
    EXPECT_EQ(pyramid["sub_texel_precision_bits"], device().info().sub_texel_precision_bits);
    EXPECT_EQ(pyramid["mipmap_precision_bits"], device().info().mipmap_precision_bits);
    EXPECT_FALSE(pyramid["mipmapping_reason"].get<std::string>().empty());
  }
  EXPECT_NE(out.markdown[0].find("Filtered sampling"), std::string::npos);
  EXPECT_NE(out.markdown[0].find("paired by round"), std::string::npos);
  EXPECT_NE(out.markdown[0].find("Copy bandwidth"), std::string::npos);
  // `compare` still loads the tables (it reads the statistics blocks, not the new ones).
  const BenchRun loaded = load_bench_run_path(root / "out");
  EXPECT_EQ(loaded.tables.size(), 2u);
  EXPECT_EQ(loaded.series.size(), 2u * 4u * 9u);
  EXPECT_NE(out.markdown[0].find("| 0.816 |"), std::string::npos);  // the paper's column

  // A second run loads the captures (no recording) and finds them identical.
  const TablesOutcome again = run_tables(device(), [&] {
    TablesOptions o2 = o;
    o2.tables = {1};
    o2.generators = {"fis_modified"};
    return o2;
  }());
  EXPECT_EQ(again.documents[0]["capture"]["recorded_now"], false);
  EXPECT_EQ(again.documents[0]["capture"]["hashes"], out.documents[0]["capture"]["hashes"]);
  EXPECT_FALSE(again.documents[0]["ratios"].contains("table1_to_table2"));  // one table: no change
}

TEST_F(TablesRunTest, CaptureHashMismatchIsRefusedAndNothingIsWritten) {
  const TempDir temp("tables_hash");
  const fs::path& root = temp.path();
  TablesOptions o = tiny_options(root);
  o.tables = {1};
  o.generators = {"fis_tok15"};
  run_tables(device(), o);
  fs::remove_all(o.out_dir);
  // Alter one recorded hash in the sidecar.
  const fs::path sidecar = root / "captures/atrium/capture.json";
  std::string text;
  {
    std::ifstream in(sidecar);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::regex first_hash("fnv1a64:[0-9a-f]{16}");
  text = std::regex_replace(text, first_hash, "fnv1a64:0123456789abcdef", std::regex_constants::format_first_only);
  std::ofstream(sidecar) << text;
  try {
    run_tables(device(), o);
    FAIL() << "a capture with a wrong hash was timed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hash mismatch"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(o.out_dir / "table1.json"));
}

// --capture: a capture that is not a paper table's (here the tiny scene) gets OUT/<scene>.json with
// "table": null, every paper value null and no paper column; a paper scene's capture is its table;
// two captures of one scene are refused; compare refuses the null table with a clear message.
TEST_F(TablesRunTest, UserCapturesGetTheirOwnTables) {
  const TempDir temp("tables_user");
  const fs::path& root = temp.path();
  record_scene_capture(device(), "tiny", RecordSizes{96, 64, 64}, 0, 1, root / "tiny");
  TablesOptions o = tiny_options(root);
  o.tables.clear();
  o.captures = {root / "tiny"};
  o.generators = {"fis_tok15", "fis_modified"};
  const TablesOutcome out = run_tables(device(), o);
  ASSERT_EQ(out.documents.size(), 1u);
  ASSERT_TRUE(fs::exists(o.out_dir / "tiny.json"));
  EXPECT_TRUE(fs::exists(o.out_dir / "tiny.md"));
  const nlohmann::ordered_json doc = read_json(o.out_dir / "tiny.json");
  EXPECT_TRUE(doc["table"].is_null());
  EXPECT_EQ(doc["scene"]["name"], "tiny");
  EXPECT_EQ(doc["scene"]["kind"], "procedural") << "the tiny scene stands in for no paper table";
  EXPECT_EQ(doc["capture"]["recorded_now"], false);
  EXPECT_TRUE(doc["generators"]["fis_modified"]["total"]["paper_ms"].is_null());
  EXPECT_GT(doc["generators"]["fis_modified"]["total"]["median_ms"].get<double>(), 0.0);
  EXPECT_TRUE(doc["ratios"]["modified_minus_tok15_us"]["total"]["paper"].is_null());
  EXPECT_EQ(doc["claims"].size(), 6u);
  EXPECT_TRUE(validate_against_schema(doc, read_json(kTableSchema)).empty());
  // No paper column in the timings or the ratios (Table 3's counts are the same for any scene).
  const std::string& md = out.markdown[0];
  EXPECT_EQ(md.substr(0, md.find("### Table 3")).find("paper |"), std::string::npos) << md;
  EXPECT_NE(out.markdown[0].find("## Scene tiny"), std::string::npos);
  EXPECT_NE(md.find("lines differ"), std::string::npos) << md;  // the FIS variants' diff and its rule
  EXPECT_NE(md.find("Counted: "), std::string::npos) << md;
  // The dashboard reads the folder such a run leaves (compare and export refuse the null table).
  const std::vector<BenchRun> drawn = find_table_runs(o.out_dir);
  ASSERT_EQ(drawn.size(), 1u);
  EXPECT_EQ(drawn[0].path, "tiny.json");
  EXPECT_NE(drawn[0].find("tiny/fis_modified/total"), nullptr);
  EXPECT_THROW(load_bench_run(o.out_dir / "tiny.json"), InputError);

  o.captures = {root / "tiny", root / "tiny"};
  try {
    run_tables(device(), o);
    FAIL() << "two captures of one scene were accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("both of scene 'tiny'"), std::string::npos) << e.what();
  }
}

TEST_F(TablesRunTest, BadOptionsAreRefusedBeforeAnyWork) {
  const TempDir temp("tables_options");
  const fs::path& root = temp.path();
  const auto with = [&](auto change) {
    TablesOptions o = tiny_options(root);
    change(o);
    return o;
  };
  EXPECT_THROW(run_tables(device(), with([](TablesOptions& o) { o.tables = {3}; })), UsageError);
  EXPECT_THROW(run_tables(device(), with([](TablesOptions& o) { o.generators = {"kmeans_4d"}; })), InputError);
  EXPECT_THROW(run_tables(device(), with([](TablesOptions& o) { o.out_dir.clear(); })), UsageError);
  EXPECT_THROW(run_tables(device(), with([](TablesOptions& o) { o.timing.warmup = 1; })), UsageError);
  EXPECT_THROW(run_tables(device(), with([](TablesOptions& o) { o.light_vsgls = 0; })), InputError);
  EXPECT_FALSE(fs::exists(root / "captures"));  // nothing recorded for a bad command line
}

TEST(TableSchema, ValidatorReportsViolations) {
  const nlohmann::ordered_json schema = nlohmann::ordered_json::parse(R"({
    "type": "object", "required": ["a", "b"], "additionalProperties": false,
    "properties": {"a": {"$ref": "#/$defs/pos"}, "b": {"type": "array", "minItems": 2, "items": {"enum": ["x", "y"]}},
                   "c": {"type": ["number", "null"]}},
    "$defs": {"pos": {"type": "number", "exclusiveMinimum": 0}}})");
  EXPECT_TRUE(validate_against_schema(nlohmann::ordered_json::parse(R"({"a": 1, "b": ["x", "y"], "c": null})"), schema)
                  .empty());
  const auto errors = validate_against_schema(nlohmann::ordered_json::parse(R"({"a": 0, "b": ["z"], "d": 1})"), schema);
  ASSERT_EQ(errors.size(), 4u);  // a not > 0, b too short, b/0 not in enum, d not allowed
  EXPECT_NE(errors[0].find("/a"), std::string::npos);
  EXPECT_FALSE(validate_against_schema(nlohmann::ordered_json::parse(R"({"a": "1"})"), schema).empty());
  EXPECT_THROW(validate_against_schema(nlohmann::ordered_json(1), nlohmann::ordered_json::parse(R"({"pattern": "x"})")),
               std::invalid_argument);  // an unsupported keyword is not silently ignored
  nlohmann::ordered_json with_nan{{"x", {{"y", std::numeric_limits<double>::quiet_NaN()}}}};
  try {
    require_finite_numbers(with_nan);
    FAIL() << "NaN accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/x/y"), std::string::npos);
  }
  // The real schema only uses what the validator enforces, in every subschema (more in
  // tests/test_json_schema_subset.cpp).
  EXPECT_EQ(schema_subset_problems(read_json(kTableSchema)), std::vector<std::string>{});
}

TEST(SourceLines, CountsCodeNotCommentsOrBlanks) {
  EXPECT_EQ(count_code_lines(""), 0u);
  EXPECT_EQ(count_code_lines("int a;\n\n   \n// only a comment\nint b; // trailing\n"), 2u);
  EXPECT_EQ(count_code_lines("/* one\n two\n three */\nx = 1; /* a */ y = 2;\n/* a */ z();\n"), 2u);
  EXPECT_EQ(count_code_lines("s = \"// not a comment\";\n"), 1u);
  EXPECT_EQ(count_code_lines("a /* open\n still comment */ b\n"), 2u);  // code on both lines
  EXPECT_EQ(count_code_lines("#include \"x.glsl\"\nlast line without newline"), 2u);

  const TempDir temp("tables_lines");
  const fs::path& root = temp.path();
  fs::create_directories(root / "kernels/include");
  std::ofstream(root / "host.cpp") << "// header comment\nint f() {\n  return 1;\n}\n";
  std::ofstream(root / "kernels/k.comp") << "#version 450\n#include \"a.glsl\"\nvoid main() {}\n";
  std::ofstream(root / "kernels/include/a.glsl") << "#include \"b.glsl\"\nfloat a;\n";
  std::ofstream(root / "kernels/include/b.glsl") << "/* b */\nfloat b;\n";
  const GeneratorLines lines = count_generator_lines(SourceSet{{"host.cpp"}, {"kernels/k.comp"}}, root);
  EXPECT_EQ(lines.total, 3u + 3u + 2u + 1u);
  ASSERT_EQ(lines.files.size(), 4u);  // transitive include closure
  EXPECT_THROW(count_generator_lines(SourceSet{{"missing.cpp"}, {}}, root), InputError);
  for (const auto& g : generator_names())
    EXPECT_GT(count_generator_lines(generator_sources(g), VSGL_SOURCE_DIR).total, 100u) << g;
}

}  // namespace
}  // namespace vsgl
