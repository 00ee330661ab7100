// The quality model (harness/formats/quality_model.hpp) against the committed quality reports:
// each results/**/quality.json reads into the model and renders as the quality.md committed beside
// it (the picture list, which is not in the JSON, left out of both); a missing field is named by
// its JSON pointer.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/json_schema_subset.hpp"
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

// A report of schema 5 as the suite wrote it (the conference stand-in's at 64b30eb, before the
// ladder): every committed report is schema 6 now, and schema 5 must still read.
fs::path committed_schema5_report() { return kSource / "tests" / "data" / "quality_schema5.json"; }

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

// A committed report read again gets its verdicts again: the claims the reference does not decide
// recomputed from the model; those it decides recomputed where the document is of the current
// rule (schema 7), kept as written where an earlier rule judged them (schema 5 and 6; DESIGN.md
// §11a *Rule*), and without a ladder and without its written claims, not decided.
TEST(QualityModel, ClaimVerdictsFromTheModelMatchTheCommittedOnes) {
  const auto reference_decided = [](const nlohmann::ordered_json& c) {
    const std::string measure = c.at("measure");
    return measure.rfind("tail error", 0) == 0 || measure.rfind("k-means margin", 0) == 0 ||
           measure.rfind("K sweep", 0) == 0;
  };
  std::vector<fs::path> reports = committed_reports();
  reports.push_back(committed_schema5_report());  // the schema-5 branch below
  for (const fs::path& f : reports) {
    SCOPED_TRACE(f.string());
    const nlohmann::ordered_json committed = read_report(f);
    const QualityModel m = quality_model_from_json(committed, f.string());
    nlohmann::ordered_json kept = committed;
    add_claim_verdicts(kept);
    EXPECT_EQ(kept["claims"], committed["claims"]);
    nlohmann::ordered_json fresh = committed;
    fresh.erase("claims");
    add_claim_verdicts(fresh);
    if (committed.at("schema_version").get<int>() >= 7) {
      EXPECT_EQ(fresh["claims"], committed["claims"]);
      continue;
    }
    ASSERT_EQ(fresh["claims"].size(), committed["claims"].size());
    for (std::size_t i = 0; i < fresh["claims"].size(); ++i) {
      const auto &a = fresh["claims"][i], &b = committed["claims"][i];
      if (!reference_decided(b)) {
        EXPECT_EQ(a, b);
        continue;
      }
      if (m.reference_detail && m.reference_detail->ladder) continue;  // judged again by today's rule
      const std::string verdict = a.at("verdict");
      if (b.at("measure").get<std::string>().rfind("K sweep", 0) != 0)
        EXPECT_EQ(verdict, "reference not converged (no reference ladder)");
      else EXPECT_NE(verdict, "holds");
    }
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

// A made-up schema-6 ladder on a committed report: relative RMSE converging at 0.5 per doubling,
// p99 with no rate (one difference: a small RSM) and a ratio that is not finite.
ReferenceLadder made_up_ladder() {
  ReferenceLadder l;
  l.rsm_strides = {8, 4, 2, 1};
  l.rsm_sides = {64, 128, 256, 512};
  l.mean_luminances = {0.03125, 0.0625, 0.046875, 0.046875};
  l.metrics["relative_rmse"] = {{0.08, 0.04, 0.02}, {0.5, 0.5}, 0.5, 0.02};
  l.metrics["p99_pixel_error"] = {{0.0, 0.5, 0.25},
                                  {std::numeric_limits<double>::infinity(), 0.5},
                                  std::numeric_limits<double>::quiet_NaN(),
                                  std::numeric_limits<double>::infinity()};
  l.note = "4 rungs, 3 successive difference(s)";
  return l;
}

// Schema 6: the ladder, the frames against the stride-2 rung and the K sweep's, written and read
// back as written (non-finite values as null), conforming to the committed schema; rendered with
// the ladder and the rule instead of schema 5's sentence.
TEST(QualityModel, SchemaSixLadderRoundTripsAndRenders) {
  QualityModel m = quality_model_from_json(read_report(committed_schema5_report()), "the report");
  ASSERT_TRUE(m.reference_detail && m.frames_static);
  EXPECT_FALSE(m.reference_detail->ladder);  // a schema-5 report has none
  m.schema_version = 6;
  m.reference_detail->ladder = made_up_ladder();
  const std::string generator = m.frames_static->generators.begin()->first;
  m.frames_static->second_rung[generator] = {{"relative_rmse", {0.25, 0.5, 0.75}}};
  m.frames_static->second_rung_reference = "the stride-2 rung";
  m.k_sweep.front().second.front().per_frame_second_rung = {{"relative_rmse", {0.125, 0.25}}};
  const nlohmann::ordered_json doc = m;
  const auto& ladder = doc["reference"]["ladder"];
  EXPECT_EQ(ladder["rsm_strides"], nlohmann::ordered_json::array({8, 4, 2, 1}));
  EXPECT_EQ(ladder["metrics"]["relative_rmse"]["rate"], 0.5);
  EXPECT_EQ(ladder["metrics"]["relative_rmse"]["remaining_error"], 0.02);
  EXPECT_TRUE(ladder["metrics"]["p99_pixel_error"]["rate"].is_null());
  EXPECT_TRUE(ladder["metrics"]["p99_pixel_error"]["remaining_error"].is_null());
  EXPECT_TRUE(ladder["metrics"]["p99_pixel_error"]["ratios"][0].is_null());
  const QualityModel back = quality_model_from_json(doc, "the report");
  ASSERT_TRUE(back.reference_detail->ladder);
  EXPECT_EQ(back.reference_detail->ladder->metrics.at("relative_rmse").differences,
            (std::vector<double>{0.08, 0.04, 0.02}));
  EXPECT_TRUE(std::isinf(back.reference_detail->ladder->metrics.at("p99_pixel_error").remaining));
  EXPECT_TRUE(std::isnan(back.reference_detail->ladder->metrics.at("p99_pixel_error").rate));
  EXPECT_EQ(back.frames_static->second_rung.at(generator).at("relative_rmse"), (std::vector<double>{0.25, 0.5, 0.75}));
  EXPECT_EQ(back.k_sweep.front().second.front().per_frame_second_rung.at("relative_rmse"),
            (std::vector<double>{0.125, 0.25}));
  const nlohmann::ordered_json again = back;
  EXPECT_EQ(again.dump(1), doc.dump(1));
  for (const std::string& problem :
       validate_against_schema(doc, read_report(kSource / "results/schema/quality.schema.json")))
    ADD_FAILURE() << problem;
  const std::string md = quality_markdown(back, {});
  EXPECT_EQ(md.find("ten times"), std::string::npos);
  EXPECT_EQ(md.find("a tenth"), std::string::npos);
  EXPECT_NE(md.find("| 8 (64^2) vs 4 (128^2) | 0 | | 0.08 | |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 2 (256^2) vs 1 (512^2), the own error | 0.25 | 0.5 | 0.02 | 0.5 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| rate rho per doubling (geometric mean of the ratios) | none | | 0.5 | |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| remaining error eps_inf = own rho / (1 - rho) | inf | | 0.02 | |"), std::string::npos) << md;
  EXPECT_NE(md.find("is decided only where (1 + b) eps_inf"), std::string::npos) << md;
  EXPECT_EQ(back.reference_detail->ladder->mean_luminances, (std::vector<double>{0.03125, 0.0625, 0.046875, 0.046875}));
  EXPECT_NE(md.find("per rung: 8 (64^2) 0.0312, 4 (128^2) 0.0625, 2 (256^2) 0.0469, 1 (512^2) 0.0469."),
            std::string::npos)
      << md;
  // One mean luminance per rung, or the document is refused by pointer.
  nlohmann::ordered_json short_by_one = doc;
  short_by_one["reference"]["ladder"]["mean_luminance"].erase(3);
  try {
    quality_model_from_json(short_by_one, "q.json");
    ADD_FAILURE() << "a ladder with 3 mean luminances for 4 rungs was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/reference/ladder/mean_luminance"), std::string::npos) << e.what();
  }
}

// A schema-6 document judges its reference claims by the ladder: without one it is refused, by
// pointer; a schema-5 document reads without it.
TEST(QualityModel, SchemaSixNeedsTheLadder) {
  nlohmann::ordered_json doc = read_report(committed_schema5_report());
  ASSERT_EQ(doc["schema_version"], 5);
  EXPECT_FALSE(quality_model_from_json(doc, "q.json").reference_detail->ladder);
  doc["schema_version"] = 6;
  try {
    quality_model_from_json(doc, "q.json");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/reference/ladder: missing field"), std::string::npos) << e.what();
  }
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
