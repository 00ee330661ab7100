// The table model (harness/formats/table_model.hpp) against the committed results: every
// results/**/table*.json reads into the model and writes back as the same document (every key,
// every value, every key order), and renders as the markdown committed beside it; bad sections
// are named by JSON pointer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "harness/compare/regression_run.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/formats/table_model.hpp"
#include "harness/report/table_markdown.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;
using test::kSource;

std::vector<fs::path> committed_tables() {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(kSource / "results"))
    if (e.is_regular_file() && is_table_file_name(e.path().filename().string())) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string text_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(TableModel, CommittedTablesRoundTripUnchanged) {
  const auto files = committed_tables();
  ASSERT_GE(files.size(), 4u);  // lavapipe and the H100, Tables 1 and 2
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    const ojson doc = read_json_file(f, "the table");
    const TableModel m = table_model_from_json(doc, f.string());
    // Every section of the file has a typed home in the model (schema v1 files have no bandwidth).
    EXPECT_TRUE(m.driver && m.paper && m.timing && m.ratios && m.table3 && m.claims);
    EXPECT_EQ(m.bandwidth.has_value(), doc.contains("bandwidth"));
    EXPECT_EQ(m.bandwidth.has_value(), m.schema_version >= 2);
    EXPECT_TRUE(m.capture.hashes.has_value());
    const ojson back = to_json(m);
    // Key by key (ordered: also the order of the keys), then the whole text as the writer writes it.
    for (const auto& [key, value] : doc.items()) {
      ASSERT_TRUE(back.contains(key)) << key;
      EXPECT_EQ(back[key].dump(), value.dump()) << key;
    }
    EXPECT_EQ(back.size(), doc.size());
    EXPECT_EQ(back.dump(2) + "\n", text_of(f));
    // The markdown committed beside a current file is the model's rendering.
    fs::path md = f;
    md.replace_extension(".md");
    if (m.schema_version == kTableSchemaVersion && fs::exists(md)) {
      EXPECT_EQ(table_markdown(m), text_of(md));
    }
  }
}

TEST(TableModel, BadSectionsAreNamedByPointer) {
  const ojson doc = read_json_file(committed_tables().front(), "the table");
  const auto message = [](const ojson& d) -> std::string {
    try {
      table_model_from_json(d, "t.json");
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  ojson bad = doc;
  bad["ratios"]["paired_modified_minus_tok15"]["total"].erase("ci_low_us");
  EXPECT_NE(message(bad).find("t.json: /ratios/paired_modified_minus_tok15/total/ci_low_us: missing field"), std::string::npos)
      << message(bad);
  bad = doc;
  bad["bandwidth"]["copy"]["samples_ms"][1] = 0.0;
  EXPECT_NE(message(bad).find("/bandwidth/copy/samples_ms/1: is not a positive time"), std::string::npos) << message(bad);
  bad = doc;
  bad["table3"]["fis_tok15"]["dispatch_calls"]["camera_view"] = -2;
  EXPECT_NE(message(bad).find("/table3/fis_tok15/dispatch_calls/camera_view"), std::string::npos) << message(bad);
  bad = doc;
  bad["claims"][0]["holds"] = "yes";
  EXPECT_NE(message(bad).find("/claims/0/holds"), std::string::npos) << message(bad);
  bad = doc;
  bad["generators"]["fis_tok15"]["views"].erase("light_view");
  EXPECT_NE(message(bad).find("/generators/fis_tok15/views/light_view: missing field"), std::string::npos) << message(bad);
}

TEST(TableModel, MarkdownNamesAMissingSection) {
  ojson doc = read_json_file(committed_tables().front(), "the table");
  doc.erase("bandwidth");
  try {
    table_markdown(doc);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bandwidth"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vsgl
