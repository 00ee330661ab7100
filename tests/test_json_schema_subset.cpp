// The schema subset validator (harness/core/json_schema_subset) against the committed schemas
// and results: every subschema uses only what it enforces, every committed result conforms to its
// kind's schema, and the deliberately broken tables and quality reports of
// tests/data/{table,quality}_schema_mutations.json are rejected (as tests/validate_results.py
// checks with python3-jsonschema: the two validators agree on them).
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
using json = nlohmann::ordered_json;
using test::read_json;

using test::kSource;

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

std::string lines_joined(const std::vector<std::string>& lines) {
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
    EXPECT_TRUE(problems.empty()) << entry.path() << ":" << lines_joined(problems);
  }
  EXPECT_GE(schemas, 1);
}

TEST(JsonSchemaSubset, FindsAnUnsupportedKeywordThreeLevelsDown) {
  const json schema = json::parse(R"({
    "type": "object",
    "properties": {"a": {"type": "array", "items": {"type": "object", "properties": {"b": {"type": "string", "pattern": "x"}}}}}})");
  const auto problems = schema_subset_problems(schema);
  ASSERT_EQ(problems.size(), 1u) << lines_joined(problems);
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
  EXPECT_FALSE(mentions(problems, "/$defs/ok")) << lines_joined(problems);
  EXPECT_EQ(problems.size(), 11u) << lines_joined(problems);
  EXPECT_TRUE(schema_subset_problems(json::parse(R"({"$ref": "#/$defs/a", "$defs": {"a": true}})")).empty());
}

// The kinds of results file (tests/data/result_kinds.json, which ci/import-device-results.sh
// and tests/validate_results.py read too): a kind's schema, or why it has none. A committed file
// of no kind fails, as does a listed exception that is gone.
struct ResultKind {
  std::string kind;
  std::regex path;
  std::string schema;  // a file of results/schema/, "by schema_version", or empty: `none` says why
  std::string none;
};

const json& result_kinds_file() {
  static const json spec = read_json(kSource / "tests/data/result_kinds.json");
  return spec;
}

std::vector<ResultKind> result_kinds() {
  std::vector<ResultKind> kinds;
  for (const json& k : result_kinds_file().at("kinds"))
    kinds.push_back({k.at("kind").get<std::string>(), std::regex("(^|/)(" + k.at("path").get<std::string>() + ")$"),
                     k.value("schema", ""), k.value("none", "")});
  return kinds;
}

// The schema a file of kind `kind` conforms to: its kind's, or for a table (tableN.json) the
// table schema of its schema_version (table.schema.json, or a frozen older one:
// table.v2.schema.json). Empty when there is none.
std::string schema_of(const ResultKind& kind, const json& doc, const std::map<std::string, json>& schemas) {
  if (kind.schema != "by schema_version") return kind.schema;
  for (const auto& [name, schema] : schemas)
    if (name.rfind("table.", 0) == 0 && doc.contains("schema_version") &&
        schema["properties"]["schema_version"]["const"] == doc["schema_version"])
      return name;
  return "";
}

TEST(CommittedResults, EveryJsonFileConformsToItsSchemaOrIsOfAKindWithoutOne) {
  std::map<std::string, json> schemas;
  for (const auto& entry : fs::directory_iterator(kSource / "results/schema"))
    schemas[entry.path().filename().string()] = read_json(entry.path());
  const auto kinds = result_kinds();
  ASSERT_GE(kinds.size(), 2u);
  const json& exceptions = result_kinds_file().at("exceptions");
  for (const ResultKind& k : kinds)
    EXPECT_TRUE(k.schema.empty() ? !k.none.empty() : k.schema == "by schema_version" || schemas.count(k.schema))
        << k.kind << ": names neither a committed schema nor why it has none";
  std::set<std::string> seen;
  int validated = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kSource / "results")) {
    if (!entry.is_regular_file() || entry.path().extension() != ".json") continue;
    const std::string rel = entry.path().lexically_relative(kSource).generic_string();
    if (rel.rfind("results/schema/", 0) == 0) continue;
    SCOPED_TRACE(rel);
    seen.insert(rel);
    const json doc = read_json(entry.path());  // throws, failing the test, when it does not parse
    if (exceptions.contains(rel)) continue;
    const auto kind =
        std::find_if(kinds.begin(), kinds.end(), [&](const ResultKind& k) { return std::regex_search(rel, k.path); });
    if (kind == kinds.end()) {
      ADD_FAILURE() << "of no kind: add its kind to tests/data/result_kinds.json (a schema, or why it has none)";
      continue;
    }
    if (kind->schema.empty()) continue;  // a kind without a schema, and why, is listed
    const std::string schema = schema_of(*kind, doc, schemas);
    if (schema.empty() || !schemas.count(schema)) {
      ADD_FAILURE() << "a " << kind->kind
                    << " whose schema is not committed: list it under exceptions in tests/data/result_kinds.json";
      continue;
    }
    const auto errors = validate_against_schema(doc, schemas.at(schema));
    EXPECT_TRUE(errors.empty()) << "against " << schema << ":" << lines_joined(errors);
    ++validated;
  }
  for (const auto& [rel, why] : exceptions.items()) EXPECT_TRUE(seen.count(rel)) << rel << ": listed but not committed";
  EXPECT_GE(validated, 2);  // results/lavapipe/table{1,2}.json at least
}

// The kinds' paths are what a GPU-machine run writes (ci/device-run.sh) as filed by
// ci/import-device-results.sh: each file lands on the kind it is.
TEST(CommittedResults, DeviceRunFilesHaveTheirKinds) {
  const auto kinds = result_kinds();
  const auto kind_of = [&](const std::string& rel) {
    for (const ResultKind& k : kinds)
      if (std::regex_search(rel, k.path)) return k.kind;
    return std::string("(none)");
  };
  EXPECT_EQ(kind_of("results/some-gpu/texture/table1.json"), "table");
  EXPECT_EQ(kind_of("results/some-gpu/sweep/sweep.json"), "sweep");
  EXPECT_EQ(kind_of("results/some-gpu/devices.json"), "devices");
  EXPECT_EQ(kind_of("results/some-gpu/verify_sponza.json"), "verify");
  EXPECT_EQ(kind_of("results/some-gpu/gbench.json"), "google-benchmark");
  EXPECT_EQ(kind_of("results/some-gpu/mipbench.json"), "google-benchmark");
  EXPECT_EQ(kind_of("results/some-gpu/tests/FisGeneratorTest.json"), "googletest");
  EXPECT_EQ(kind_of("results/some-gpu/mytable1.json"), "(none)");
  EXPECT_EQ(kind_of("results/some-gpu/notes.json"), "(none)");
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

// Each mutation of `spec_file` ({base, schema, mutations}) turns its committed base file into one
// the schema must refuse: the schema checks what it says, down into the nested objects.
void expect_mutations_rejected(const std::string& spec_file) {
  const json spec = read_json(kSource / spec_file);
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

TEST(CommittedResults, DeliberatelyBrokenTablesAreRejected) {
  expect_mutations_rejected("tests/data/table_schema_mutations.json");
}

TEST(CommittedResults, DeliberatelyBrokenQualityReportsAreRejected) {
  expect_mutations_rejected("tests/data/quality_schema_mutations.json");
}

}  // namespace
}  // namespace vsgl
