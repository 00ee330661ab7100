// The files built into the programs (cmake/Embed.cmake, harness/core/embedded_files.hpp; DESIGN.md
// §10): each is the checkout's file byte for byte (an edit without a rebuild fails here), the
// inputs the programs read by default are among them, and a name not built in is none.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "harness/core/embedded_files.hpp"
#include "harness/core/error.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/report/tables_run.hpp"
#include "harness/sweep/sweep_run.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

std::string checkout_text(const std::string& rel) {
  std::ifstream in(fs::path(VSGL_SOURCE_DIR) / rel, std::ios::binary);
  EXPECT_TRUE(in.good()) << rel;
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(EmbeddedFiles, EachIsTheCheckoutsFileByteForByte) {
  const std::vector<std::string> names = embedded_file_names();
  ASSERT_FALSE(names.empty());
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  for (const std::string& name : names) {
    const std::optional<std::string_view> text = embedded_file(name);
    ASSERT_TRUE(text.has_value()) << name;
    EXPECT_EQ(std::string(*text), checkout_text(name)) << name << ": rebuild to embed the edited file";
  }
}

TEST(EmbeddedFiles, TheDefaultInputsAreBuiltInAndParse) {
  for (const char* name : {kPaperTablesFile, kTableSchemaFile, kSweepSchemaFile, "harness/scene/presets/sponza.json",
                           "harness/scene/presets/conference-room.json"})
    EXPECT_TRUE(embedded_file(name).has_value()) << name;
  const nlohmann::ordered_json paper = paper_tables_or_built_in(std::nullopt);
  EXPECT_EQ(paper, load_paper_tables(fs::path(VSGL_SOURCE_DIR) / kPaperTablesFile));
  EXPECT_EQ(json_file_or_built_in(std::nullopt, kTableSchemaFile, "the table schema", ""),
            json_file_or_built_in(fs::path(VSGL_SOURCE_DIR) / kTableSchemaFile, kTableSchemaFile, "", ""));
  EXPECT_EQ(file_or_built_in_name(std::nullopt, kPaperTablesFile), "results/paper/paper_tables.json (built in)");
  EXPECT_EQ(file_or_built_in_name(fs::path("p.json"), kPaperTablesFile), "p.json");
}

TEST(EmbeddedFiles, ANameNotBuiltInIsNoneAndAnErrorWhereItIsNeeded) {
  EXPECT_FALSE(embedded_file("results/paper/no_such.json").has_value());
  EXPECT_FALSE(embedded_file("").has_value());
  EXPECT_TRUE(embedded_file_names("no/such/prefix/").empty());
  try {
    (void)embedded_json("results/schema/no_such.schema.json", "the table schema");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such.schema.json (built in)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vsgl
