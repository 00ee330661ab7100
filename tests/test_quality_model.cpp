// The quality model (harness/formats/quality_model.hpp) against the committed quality reports:
// each results/**/quality.json reads into the model and renders as the quality.md committed beside
// it (the picture list, which is not in the JSON, left out of both); a missing field is named by
// its JSON pointer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/formats/quality_model.hpp"
#include "harness/quality/quality_claims.hpp"
#include "harness/quality/quality_report.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using test::kSource;

std::vector<fs::path> committed_reports() {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(kSource / "results"))
    if (e.is_regular_file() && e.path().filename() == "quality.json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

nlohmann::ordered_json read_report(const fs::path& p) { return read_json_file(p, "the report"); }

// The markdown without the lines of the picture list.
std::string without_pictures(const std::string& md) {
  const std::string head = "\n## Pictures\n\n", tail = "\n## Run time";
  const auto a = md.find(head), b = md.find(tail);
  if (a == std::string::npos || b == std::string::npos || b < a) return md;
  return md.substr(0, a + head.size()) + md.substr(b);
}

TEST(QualityModel, CommittedReportsRenderAsCommitted) {
  const auto files = committed_reports();
  ASSERT_GE(files.size(), 2u);  // atrium and conference
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    const QualityModel m = quality_model_from_json(read_report(f), f.string());
    EXPECT_EQ(m.views.size(), 2u);
    ASSERT_TRUE(m.claims);
    EXPECT_FALSE(m.claims->empty());
    std::ifstream in(fs::path(f).replace_filename("quality.md"), std::ios::binary);
    std::ostringstream committed;
    committed << in.rdbuf();
    EXPECT_EQ(quality_markdown(m, {}), without_pictures(committed.str()));
  }
}

TEST(QualityModel, ClaimVerdictsFromTheModelMatchTheCommittedOnes) {
  for (const fs::path& f : committed_reports()) {
    SCOPED_TRACE(f.string());
    const nlohmann::ordered_json committed = read_report(f);
    nlohmann::ordered_json doc = committed;
    doc.erase("claims");
    add_claim_verdicts(doc);
    EXPECT_EQ(doc["claims"], committed["claims"]);
  }
}

// The writer serialises the model (run_quality fills a QualityModel and writes its to_json), so the
// model must carry every field of a written document: each committed report reads into the model
// and writes back as the same tree, numbers of the same kind (integer or floating) and all.
TEST(QualityModel, CommittedReportsRoundTripThroughTheModel) {
  for (const fs::path& f : committed_reports()) {
    SCOPED_TRACE(f.string());
    const nlohmann::ordered_json doc = read_report(f);
    const nlohmann::ordered_json written = quality_model_from_json(doc, f.string());
    EXPECT_EQ(written, doc);
    EXPECT_EQ(written.dump(1), doc.dump(1));
  }
}

// The typed fields are what is written, over the raw build and configuration they were read with.
TEST(QualityModel, TypedFieldsAreWrittenOverTheRawOnes) {
  QualityModel m = quality_model_from_json(read_report(committed_reports().front()), "the report");
  m.build.git_commit = "0123";
  m.generators = {"fis_modified"};
  m.views.at("light_view").generators.at("fis_modified").power.power_ratio = 0.5;
  const nlohmann::ordered_json j = m;
  EXPECT_EQ(j["build"]["git_commit"], "0123");
  EXPECT_EQ(j["config"]["generators"], nlohmann::ordered_json::array({"fis_modified"}));
  EXPECT_EQ(j["views"]["light_view"]["generators"]["fis_modified"]["power"]["power_ratio"], 0.5);
}

// Schema 4's flux origin (quality/flux_origin.hpp) reads, writes back as written, and renders.
TEST(QualityModel, FluxOriginRoundTripsAndRenders) {
  QualityModel m = quality_model_from_json(read_report(committed_reports().front()), "the report");
  m.schema_version = 4;
  ViewQuality& light = m.views.at("light_view");
  light.flux_by_pdf =
      FluxByPdfSummary{{1e-3, 1e-2, 1e-1}, {10, 20, 30, 40, 0}, {0.25, 0.125, 0.5, 0.125, 0.0}, 2.0, "d"};
  light.generators.at("fis_modified").flux_origin =
      FluxOriginSummary{{0.0625, 0.0, 0.5, 0.125, 0.0}, {0.0, 0.0, 0.0, 0.0, 0.0}, 0.6875, 1.0, 0.0, std::nullopt};
  light.generators.at("fis_tok15").flux_origin = FluxOriginSummary{
      {0.125, 0.0, 0.5, 0.125, 0.0},
      {0.0625, 0.0, 0.0, 0.0, 0.0},
      0.75,
      1.125,
      0.03125,
      FluxOriginFrames{
          4, {0.125, 0.0, 0.5, 0.125, 0.0}, {0.01, 0.0, 0.02, 0.0, 0.0}, 0.75, 0.0625, 0.625, 0.875, 0.25}};
  const nlohmann::ordered_json doc = m;
  const nlohmann::ordered_json again = quality_model_from_json(doc, "the report");
  EXPECT_EQ(again.dump(1), doc.dump(1));
  EXPECT_TRUE(doc["views"]["light_view"]["flux_by_pdf"]["texels"][0].is_number_integer());
  const std::string md = quality_markdown(m, {});
  EXPECT_NE(md.find("## Where the power comes from"), std::string::npos);
  EXPECT_NE(md.find("| q = 0 | 10 | 0.25 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 0.001 <= e < 0.01 | 30 | 0.5 |"), std::string::npos) << md;
  EXPECT_NE(md.find("fis_tok15 over 4 lattice offsets: sum Phi / flux mean 0.75 (stdev 0.0625, 0.625 to 0.875)"),
            std::string::npos)
      << md;
}

TEST(QualityModel, MissingFieldsAreNamedByPointer) {
  nlohmann::ordered_json doc = read_report(committed_reports().front());
  doc["views"]["light_view"]["generators"]["fis_tok15"]["coverage"]["excess"]["eq3"].erase("count_error");
  try {
    quality_markdown(doc, {});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/views/light_view/generators/fis_tok15/coverage/excess/eq3/count_error: missing field"),
              std::string::npos)
        << e.what();
  }
}

// A per-frame series is summarized (mean, 95th percentile, maximum) by core's summarize, which
// needs 2 values: a series of one frame is refused by pointer, never summarized as a NaN.
TEST(QualityModel, AFrameSeriesNeedsTwoFrames) {
  nlohmann::ordered_json doc = read_report(committed_reports().front());
  const std::string generator = doc["frames_static"]["generators"].begin().key();
  auto& per_frame = doc["frames_static"]["generators"][generator]["series"]["relative_rmse"]["per_frame"];
  per_frame = nlohmann::ordered_json::array({per_frame[0]});
  try {
    quality_model_from_json(doc, "q.json");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/frames_static/generators/" + generator +
                                         "/series/relative_rmse/per_frame: has 1 frame(s); a series needs at least 2"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace vsgl
