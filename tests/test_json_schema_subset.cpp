// The schema subset validator (harness/core/json_schema_subset) against the committed schemas
// and results: every subschema uses only what it enforces, every committed table conforms, and
// the deliberately broken tables of tests/data/table_schema_mutations.json are rejected (as
// tests/validate_results.py checks with python3-jsonschema: the two validators agree on them).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/core/json_schema_subset.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::read_json;

const fs::path kSource = VSGL_SOURCE_DIR;

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += "\n  " + l;
  return out;
}

TEST(JsonSchemaSubset, EveryCommittedSchemaUsesOnlyWhatTheValidatorEnforces) {
  int schemas = 0;
  for (const auto& entry : fs::directory_iterator(kSource / "results/schema")) {
    if (entry.path().extension() != ".json") continue;
    ++schemas;
    const auto problems = schema_subset_problems(read_json(entry.path()));
    EXPECT_TRUE(problems.empty()) << entry.path() << ":" << joined(problems);
  }
  EXPECT_GE(schemas, 1);
}

TEST(JsonSchemaSubset, FindsAnUnsupportedKeywordThreeLevelsDown) {
  const json schema = json::parse(R"({
    "type": "object",
    "properties": {"a": {"type": "array", "items": {"type": "object", "properties": {"b": {"type": "string", "pattern": "x"}}}}}})");
  const auto problems = schema_subset_problems(schema);
  ASSERT_EQ(problems.size(), 1u) << joined(problems);
  EXPECT_EQ(problems[0].rfind("/properties/a/items/properties/b/pattern:", 0), 0u) << problems[0];
  // The validator refuses the schema even for a document that never reaches that subschema.
  EXPECT_THROW(validate_against_schema(json::object(), schema), std::invalid_argument);
}

TEST(JsonSchemaSubset, WalksUnderKeywordsOutsideTheSubsetAndChecksValues) {
  const json schema = json::parse(R"({
    "allOf": [{"properties": {"c": {"minimum": "1"}}}],
    "definitions": {"d": {"not": {"format": "date"}}},
    "properties": {"e": {"$ref": "#/$defs/missing"}, "f": {"type": "integr"}, "g": {"minItems": -1},
                   "h": {"additionalProperties": {"$defs": {}}}, "i": {"items": [{"type": "string"}]},
                   "j": {"required": "k"}},
    "$defs": {"ok": {"type": ["number", "null"], "exclusiveMinimum": 0, "enum": [1, null], "const": 1}}})");
  const auto problems = schema_subset_problems(schema);
  EXPECT_TRUE(mentions(problems, "/allOf: keyword 'allOf'"));
  EXPECT_TRUE(mentions(problems, "/allOf/0/properties/c/minimum: must be a number"));
  EXPECT_TRUE(mentions(problems, "/definitions: keyword 'definitions'"));
  EXPECT_TRUE(mentions(problems, "/definitions/d/not: keyword 'not'"));
  EXPECT_TRUE(mentions(problems, "/definitions/d/not/format: keyword 'format'"));
  EXPECT_TRUE(mentions(problems, "/properties/e/$ref:"));
  EXPECT_TRUE(mentions(problems, "/properties/f/type: names no JSON type"));
  EXPECT_TRUE(mentions(problems, "/properties/g/minItems:"));
  EXPECT_TRUE(mentions(problems, "/properties/h/additionalProperties/$defs: $defs only at the root"));
  EXPECT_TRUE(mentions(problems, "/properties/i/items: must be one schema"));
  EXPECT_TRUE(mentions(problems, "/properties/j/required:"));
  EXPECT_FALSE(mentions(problems, "/$defs/ok")) << joined(problems);
  EXPECT_EQ(problems.size(), 11u) << joined(problems);
  EXPECT_TRUE(schema_subset_problems(json::parse(R"({"$ref": "#/$defs/a", "$defs": {"a": true}})")).empty());
}

// Committed JSON under results/ that no schema in results/schema/ describes, and why. A new file
// must be mapped to a schema below or listed here; a listed file that is gone fails too.
const std::map<std::string, std::string>& without_schema() {
  static const std::map<std::string, std::string> files = {
      {"results/lavapipe/stand-ins/quality/atrium/quality.json",
       "the quality report (vsgl-bench quality) has no schema yet"},
      {"results/lavapipe/stand-ins/quality/conference/quality.json",
       "the quality report (vsgl-bench quality) has no schema yet"},
      {"results/lavapipe/stand-ins/verify_atrium.json", "vsgl-bench verify --json output has no schema yet"},
      {"results/lavapipe/stand-ins/verify_conference.json", "vsgl-bench verify --json output has no schema yet"},
      {"results/lavapipe/quality/sponza/quality.json", "the quality report (vsgl-bench quality) has no schema yet"},
      {"results/lavapipe/quality/conference-room/quality.json",
       "the quality report (vsgl-bench quality) has no schema yet"},
      {"results/lavapipe/verify_sponza.json", "vsgl-bench verify --json output has no schema yet"},
      {"results/lavapipe/verify_conference-room.json", "vsgl-bench verify --json output has no schema yet"},
      {"results/nvidia-h100-80gb-hbm3/verify_atrium.json", "vsgl-bench verify --json output has no schema yet"},
      {"results/nvidia-h100-80gb-hbm3/verify_conference.json", "vsgl-bench verify --json output has no schema yet"},
      {"results/swiftshader/verify_atrium.json", "vsgl-bench verify --json output has no schema yet"},
      {"results/swiftshader/verify_conference.json", "vsgl-bench verify --json output has no schema yet"},
      {"results/nvidia-h100-80gb-hbm3/devices.json", "vsgl-bench devices --json output has no schema yet"},
      {"results/nvidia-h100-80gb-hbm3/gbench.json", "Google Benchmark's own JSON format, not ours"},
      {"results/paper/paper_tables.json", "the paper's numbers, an input checked by the code that loads it"},
      {"results/nvidia-h100-80gb-hbm3/table1.json",
       "a schema_version 1 table, recorded before table.schema.json version 2; no version 1 schema is committed"},
      {"results/nvidia-h100-80gb-hbm3/table2.json",
       "a schema_version 1 table, recorded before table.schema.json version 2; no version 1 schema is committed"},
  };
  return files;
}

// The schema a committed file conforms to: a sweep (sweep.json) to sweep.schema.json; a table
// (tableN.json) to the table schema of its schema_version (table.schema.json, or a frozen older
// one: table.v2.schema.json).
std::string schema_of(const fs::path& file, const json& doc, const std::map<std::string, json>& schemas) {
  static const std::regex table(R"(table\d+\.json)");
  if (file.filename() == "sweep.json") return "sweep.schema.json";
  if (!std::regex_match(file.filename().string(), table)) return "";
  for (const auto& [name, schema] : schemas)
    if (name.rfind("table.", 0) == 0 && doc.contains("schema_version") &&
        schema["properties"]["schema_version"]["const"] == doc["schema_version"])
      return name;
  return "";
}

TEST(CommittedResults, EveryJsonFileConformsToItsSchemaOrIsListedWithoutOne) {
  std::map<std::string, json> schemas;
  for (const auto& entry : fs::directory_iterator(kSource / "results/schema"))
    schemas[entry.path().filename().string()] = read_json(entry.path());
  std::set<std::string> seen;
  int validated = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kSource / "results")) {
    if (!entry.is_regular_file() || entry.path().extension() != ".json") continue;
    const std::string rel = entry.path().lexically_relative(kSource).generic_string();
    if (rel.rfind("results/schema/", 0) == 0) continue;
    SCOPED_TRACE(rel);
    seen.insert(rel);
    const json doc = read_json(entry.path());  // throws, failing the test, when it does not parse
    if (without_schema().count(rel)) continue;
    const std::string schema = schema_of(entry.path(), doc, schemas);
    if (schema.empty() || !schemas.count(schema)) {
      ADD_FAILURE() << "no schema describes it: map it to one in schema_of() or list it in without_schema()";
      continue;
    }
    const auto errors = validate_against_schema(doc, schemas.at(schema));
    EXPECT_TRUE(errors.empty()) << "against " << schema << ":" << joined(errors);
    ++validated;
  }
  for (const auto& [rel, why] : without_schema()) EXPECT_TRUE(seen.count(rel)) << rel << ": listed but not committed";
  EXPECT_GE(validated, 2);  // results/lavapipe/table{1,2}.json at least
}

json mutated(json doc, const json& mutation) {
  if (mutation.contains("set")) {
    doc[json::json_pointer(mutation["set"].get<std::string>())] = mutation["value"];
  } else {
    const json::json_pointer where(mutation["remove"].get<std::string>());
    doc.at(where.parent_pointer()).erase(where.back());
  }
  return doc;
}

TEST(CommittedResults, DeliberatelyBrokenTablesAreRejected) {
  const json spec = read_json(kSource / "tests/data/table_schema_mutations.json");
  const json base = read_json(kSource / spec["base"].get<std::string>());
  const json schema = read_json(kSource / spec["schema"].get<std::string>());
  ASSERT_TRUE(validate_against_schema(base, schema).empty());
  ASSERT_GE(spec["mutations"].size(), 5u);
  for (const json& m : spec["mutations"]) {
    SCOPED_TRACE(m["what"].get<std::string>());
    const json broken = mutated(base, m);
    ASSERT_NE(broken, base);  // the pointer reached something
    EXPECT_FALSE(validate_against_schema(broken, schema).empty()) << "accepted";
  }
}

}  // namespace
}  // namespace vsgl
