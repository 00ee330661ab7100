// The frame model (harness/formats/frame_model.hpp): a model written, read and written again is the
// same document, it conforms to results/schema/frame.schema.json (the copy in the checkout and the
// one built into the program), and the reader refuses a broken document naming the JSON pointer.
#include <gtest/gtest.h>

#include <string>

#include "harness/core/embedded_files.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/formats/frame_model.hpp"
#include "synthetic_frame.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

TEST(FrameModel, RoundTripsAndConformsToItsSchema) {
  const ojson doc = to_json(test::synthetic_frame());
  const FrameModel back = frame_model_from_json(doc, "frame.json");
  EXPECT_EQ(to_json(back).dump(), doc.dump());
  ASSERT_EQ(back.generators.size(), 2u);
  EXPECT_EQ(back.generators[1].phases[2].phase, "vsgl_generation");
  const ojson checkout = test::read_json(test::kSource / kFrameSchemaFile);
  EXPECT_TRUE(schema_subset_problems(checkout).empty());
  const auto problems = validate_against_schema(doc, checkout);
  EXPECT_TRUE(problems.empty()) << problems.front();
  // The program validates against its built-in copy: the same file.
  EXPECT_EQ(json_file_or_built_in(std::nullopt, kFrameSchemaFile, "the frame schema", ""), checkout);
  // The markdown names every phase with its median and share, and the frame.
  const std::string md = frame_markdown(back);
  for (const auto& p : frame_phase_names()) EXPECT_NE(md.find("| " + p + " | "), std::string::npos) << p;
  EXPECT_NE(md.find("| **frame** | **"), std::string::npos);
  EXPECT_NE(md.find("rsm_replay`: the recorded RSM copied"), std::string::npos);
  EXPECT_NE(md.find("Not the paper's sizes"), std::string::npos);
}

// Each mutation is refused with the pointer of what it broke, and the schema also rejects it.
TEST(FrameModel, ReaderRefusesBrokenDocumentsByPointer) {
  const ojson good = to_json(test::synthetic_frame());
  const ojson schema = test::read_json(test::kSource / kFrameSchemaFile);
  struct Mutation {
    const char* pointer;
    void (*mutate)(ojson&);
  };
  const Mutation mutations[] = {
      {"/generators/0/frame/samples_ms/2", [](ojson& d) { d["generators"][0]["frame"]["samples_ms"][2] = 99.0; }},
      {"/generators/1/phases", [](ojson& d) { d["generators"][1]["phases"].erase("ism"); }},
      {"/generators/0/phases/pdf/median_ms", [](ojson& d) { d["generators"][0]["phases"]["pdf"]["median_ms"] = -1.0; }},
      {"/capture/visibility_points", [](ojson& d) { d["capture"].erase("visibility_points"); }},
      {"/config/stride", [](ojson& d) { d["config"]["stride"] = "two"; }},
      {"/timing/repetitions", [](ojson& d) { d["timing"]["repetitions"] = 4; }},
      {"/kind", [](ojson& d) { d["kind"] = "table"; }},
  };
  for (const Mutation& m : mutations) {
    SCOPED_TRACE(m.pointer);
    ojson doc = good;
    m.mutate(doc);
    try {
      (void)frame_model_from_json(doc, "frame.json");
      ADD_FAILURE() << "read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(m.pointer), std::string::npos) << e.what();
    }
  }
  // The schema holds the shape (the per-round sum is the reader's check alone).
  ojson missing = good;
  missing["generators"][1]["phases"].erase("ism");
  EXPECT_FALSE(validate_against_schema(missing, schema).empty());
}

}  // namespace
}  // namespace vsgl
