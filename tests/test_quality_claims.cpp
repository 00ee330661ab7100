// The quality claims' verdicts (DESIGN.md §11a.1, quality/quality_claims.hpp) on made-up per-frame
// series whose answer is known: a clear reduction holds, a clear increase does not hold, a series
// that straddles the bound is inconclusive, and a claim on an error against the reference is
// "reference not converged" when the reference's own error is not below a tenth of the distance.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "harness/core/generator_ids.hpp"
#include "harness/formats/quality_model.hpp"
#include "harness/quality/quality_claims.hpp"

namespace vsgl {
namespace {

const std::string kTok(kFisTok15), kMod(kFisModified), kKm3(kKmeans3d);

// 32 frames of `base` times a small frame-to-frame wobble, scaled by `factor`.
std::vector<double> frames_of(double base, double factor) {
  std::vector<double> v;
  for (int f = 0; f < 32; ++f) v.push_back(factor * base * (1.0 + 0.02 * ((f * 7) % 5 - 2)));
  return v;
}

// The smallest document the model reads: every required field present, values made up.
QualityModel minimal_model() {
  QualityModel m;
  m.schema_version = 5;
  m.scene = "made-up";
  m.gbuffer_size = nlohmann::ordered_json::array({16, 8});
  m.rsm_size = nlohmann::ordered_json::array({8, 8});
  m.capture_hashes = nlohmann::ordered_json::object();
  m.generators = {kTok, kMod, kKm3};
  m.light_vsgls = 16;
  m.camera_vsgls = 16;
  m.K = 1.0;
  m.frames = 32;
  for (const char* view : {"light_view", "camera_view"}) m.views[view].vsgls = 16;
  m.reference_vpls = 64;
  m.reference_rsm_side = 8;
  m.reference_rsm_stride = 1;
  m.reference_image = nlohmann::ordered_json::array({16, 8});
  m.flicker_image = nlohmann::ordered_json::array({16, 8});
  m.flicker_gbuffer_stride = 1;
  for (const auto& g : m.generators) {
    m.reference_error[g] = {};
    m.flicker_static[g] = {0.1, 0.0, 0.0, 32};
  }
  ReferenceDetail d;
  d.own_errors = {{"relative_rmse", 0.001}, {"p99_pixel_error", 0.001}};
  m.reference_detail = d;
  FrameErrors f;
  f.gbuffer_stride = 1;
  f.image = nlohmann::ordered_json::array({16, 8});
  f.reference = "made up";
  m.frames_static = f;
  return m;
}

// The verdict of the one claim whose measure starts with `measure`.
std::string verdict_of(const nlohmann::ordered_json& doc, const std::string& measure) {
  std::string found;
  int n = 0;
  for (const auto& c : doc.at("claims"))
    if (c.at("measure").get<std::string>().rfind(measure, 0) == 0) {
      found = c.at("verdict").get<std::string>();
      ++n;
    }
  EXPECT_EQ(n, 1) << measure;
  return found;
}

TEST(QualityClaims, PairedFramesDecideHoldsDoesNotHoldAndInconclusive) {
  QualityModel m = minimal_model();
  FrameSeries& tok = m.frames_static->generators[kTok];
  FrameSeries& mod = m.frames_static->generators[kMod];
  tok["light_view_max_over_mean"] = frames_of(20.0, 1.0);
  mod["light_view_max_over_mean"] = frames_of(20.0, 0.5);  // half: holds
  tok["camera_view_max_over_mean"] = frames_of(5.0, 1.0);
  mod["camera_view_max_over_mean"] = frames_of(5.0, 1.2);  // 20 % brighter: does not hold
  tok["flicker_deviation"] = frames_of(0.1, 1.0);
  mod["flicker_deviation"] = tok["flicker_deviation"];
  for (std::size_t f = 0; f < 32; ++f) mod["flicker_deviation"][f] *= f % 2 == 0 ? 0.9 : 1.08;  // about 0.99
  tok["light_view_coverage_excess"] = frames_of(0.10, 1.0);
  mod["light_view_coverage_excess"] = frames_of(0.05, 1.0);  // 0.05 lower: below -0.02, holds
  nlohmann::ordered_json doc = m;
  add_claim_verdicts(doc);
  EXPECT_EQ(verdict_of(doc, "light_view: too-bright"), "holds");
  EXPECT_EQ(verdict_of(doc, "camera_view: too-bright"), "does not hold");
  EXPECT_EQ(verdict_of(doc, "static flicker").rfind("inconclusive", 0), 0u) << verdict_of(doc, "static flicker");
  EXPECT_EQ(verdict_of(doc, "light_view: coverage excess"), "holds");
  // Read back, each is the one verdict type with its outcome (the file has no other key for it).
  const QualityModel back = quality_model_from_json(doc, "made up");
  ASSERT_TRUE(back.claims.has_value());
  std::vector<std::string> outcomes;
  for (const Claim& c : *back.claims)
    if (c.criterion.find("too-bright") != std::string::npos || c.criterion.rfind("static flicker", 0) == 0)
      outcomes.push_back(claim_verdict(c));
  EXPECT_EQ(outcomes, (std::vector<std::string>{"holds", "does not hold", "inconclusive"}));
  // The claim keeps what it was judged on: the means, the interval and the bound.
  for (const auto& c : doc.at("claims"))
    if (c.at("measure").get<std::string>().rfind("light_view: too-bright", 0) == 0) {
      EXPECT_NEAR(c.at(kMod).get<double>() / c.at(kTok).get<double>(), 0.5, 1e-12);
      EXPECT_LT(c.at("interval")[1].get<double>(), 0.99);
      EXPECT_EQ(c.at("frames"), 32);
      EXPECT_EQ(c.at("bound"), 0.99);
    }
}

TEST(QualityClaims, AnErrorClaimWaitsForAConvergedReference) {
  QualityModel m = minimal_model();
  FrameSeries& tok = m.frames_static->generators[kTok];
  FrameSeries& mod = m.frames_static->generators[kMod];
  FrameSeries& km = m.frames_static->generators[kKm3];
  tok["p99_pixel_error"] = frames_of(2.0, 1.0);
  mod["p99_pixel_error"] = frames_of(2.0, 0.8);
  tok["relative_rmse"] = frames_of(0.3, 1.0);
  mod["relative_rmse"] = frames_of(0.3, 1.0);
  km["relative_rmse"] = frames_of(0.3, 1.0);  // modified equal to k-means: within 10 %
  nlohmann::ordered_json converged = m;
  add_claim_verdicts(converged);
  EXPECT_EQ(verdict_of(converged, "tail error"), "holds");
  EXPECT_EQ(verdict_of(converged, "k-means margin, kmeans_3d"), "holds");
  // The reference's own p99 error 0.05: 10 x 0.05 = 0.5 is not below the distance |1.6 - 2.0| = 0.4.
  m.reference_detail->own_errors["p99_pixel_error"] = 0.05;
  nlohmann::ordered_json unconverged = m;
  add_claim_verdicts(unconverged);
  EXPECT_EQ(verdict_of(unconverged, "tail error").rfind("reference not converged", 0), 0u);
  EXPECT_EQ(verdict_of(unconverged, "k-means margin, kmeans_3d"), "holds");
  // The worst frame must agree with the interval.
  m.reference_detail->own_errors["p99_pixel_error"] = 0.001;
  mod["p99_pixel_error"][3] = 10.0;
  nlohmann::ordered_json worst = m;
  add_claim_verdicts(worst);
  EXPECT_NE(verdict_of(worst, "tail error"), "holds");
}

TEST(QualityClaims, TheKSweepHoldsOnlyWhenEveryStepDoes) {
  QualityModel m = minimal_model();
  const auto sweep = [&](double error_at_k8) {
    std::vector<KSweepRow> rows;
    const double ks[] = {1, 2, 4, 8}, flicker[] = {0.2, 0.15, 0.1, 0.05}, error[] = {0.2, 0.25, 0.3, error_at_k8};
    for (int i = 0; i < 4; ++i) {
      KSweepRow row;
      row.K = ks[i];
      row.frames = 32;
      row.per_frame = {{"flicker_deviation", frames_of(flicker[i], 1.0)}, {"relative_rmse", frames_of(error[i], 1.0)}};
      rows.push_back(row);
    }
    return rows;
  };
  m.k_sweep = {{kMod, sweep(0.35)}, {kTok, sweep(0.2)}};  // Tok15's error falls at the last step
  nlohmann::ordered_json doc = m;
  add_claim_verdicts(doc);
  EXPECT_EQ(verdict_of(doc, "K sweep, fis_modified"), "holds");
  EXPECT_EQ(verdict_of(doc, "K sweep, fis_tok15"), "does not hold");
}

TEST(QualityClaims, ADocumentWithoutFrameSeriesIsNotJudged) {
  QualityModel m = minimal_model();
  m.frames_static.reset();
  nlohmann::ordered_json doc = m;
  add_claim_verdicts(doc);
  EXPECT_EQ(doc.at("claims")[0].at("verdict").get<std::string>().rfind("not measured here", 0), 0u);
}

}  // namespace
}  // namespace vsgl
