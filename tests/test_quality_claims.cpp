// The quality claims' verdicts (DESIGN.md §11a.1, quality/quality_claims.hpp) on made-up per-frame
// series whose answer is known: a clear reduction holds, a clear increase does not hold, a series
// that straddles the bound is inconclusive; and the reference's rule (DESIGN.md §11a *Rule*,
// quality/quality_reference.hpp) on made-up ladders: a claim on an error against the reference is
// "reference not converged" unless (1 + b) eps_inf is below the distance and its verdict against
// the stride-2 rung is the same.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "harness/core/generator_ids.hpp"
#include "harness/formats/quality_model.hpp"
#include "harness/quality/quality_claims.hpp"
#include "harness/quality/quality_reference.hpp"

namespace vsgl {
namespace {

const std::string kTok(kFisTok15), kMod(kFisModified), kKm3(kKmeans3d);

// 32 frames of `base` times a small frame-to-frame wobble, scaled by `factor`.
std::vector<double> frames_of(double base, double factor) {
  std::vector<double> v;
  for (int f = 0; f < 32; ++f) v.push_back(factor * base * (1.0 + 0.02 * ((f * 7) % 5 - 2)));
  return v;
}

// A ladder of three successive differences falling by `rate` per rung down to `own`.
ReferenceLadderMetric ladder_of(double own, double rate) {
  return reference_ladder_metric({own / (rate * rate), own / rate, own});
}

// The smallest document the model reads: every required field present, values made up; a
// converged reference (eps_inf 0.001 in both metrics the claims judge).
QualityModel minimal_model() {
  QualityModel m;
  m.schema_version = 6;
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
  ReferenceLadder ladder;
  ladder.rsm_strides = {8, 4, 2, 1};
  ladder.rsm_sides = {1, 2, 4, 8};
  ladder.metrics = {{"relative_rmse", ladder_of(0.001, 0.5)}, {"p99_pixel_error", ladder_of(0.001, 0.5)}};
  ladder.note = "made up";
  d.ladder = ladder;
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

// The claim object of the one claim whose measure starts with `measure`.
nlohmann::ordered_json claim_of(const nlohmann::ordered_json& doc, const std::string& measure) {
  for (const auto& c : doc.at("claims"))
    if (c.at("measure").get<std::string>().rfind(measure, 0) == 0) return c;
  ADD_FAILURE() << measure;
  return {};
}

bool not_converged(const std::string& verdict) { return verdict.rfind("reference not converged", 0) == 0; }

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
  // Against the stride-2 rung the same frames, a little higher: the same verdicts.
  for (const std::string& g : {kTok, kMod, kKm3})
    for (const char* metric : {"p99_pixel_error", "relative_rmse"})
      if (m.frames_static->generators[g].contains(metric))
        for (double v : m.frames_static->generators[g][metric])
          m.frames_static->second_rung[g][metric].push_back(1.01 * v);
  nlohmann::ordered_json converged = m;
  add_claim_verdicts(converged);
  EXPECT_EQ(verdict_of(converged, "tail error"), "holds");
  EXPECT_EQ(verdict_of(converged, "k-means margin, kmeans_3d"), "holds");
  // The claim keeps what the rule read: eps_inf 0.001, (1 + 1) x 0.001, the distance |1.6 - 2.0|,
  // and the second rung's verdict.
  const auto tail = claim_of(converged, "tail error");
  EXPECT_EQ(tail.at("reference_metric"), "p99_pixel_error");
  EXPECT_NEAR(tail.at("reference_own_error").get<double>(), 0.001, 1e-15);
  EXPECT_NEAR(tail.at("reference_rate").get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(tail.at("reference_remaining_error").get<double>(), 0.001, 1e-12);
  EXPECT_NEAR(tail.at("reference_margin").get<double>(), 0.002, 1e-12);
  EXPECT_NEAR(tail.at("judged_distance").get<double>(), 0.2 * tail.at(kTok).get<double>(), 1e-12);
  EXPECT_EQ(tail.at("second_rung").at("verdict"), "holds");
  EXPECT_LT(tail.at("second_rung").at("interval")[1].get<double>(), 1.0);

  // The p99 ladder at 0.9 per doubling, own 0.05: eps_inf = 0.45, and (1 + 1) x 0.45 = 0.9 is not
  // below the distance 0.2 x 1.9975 (the frames' mean). The k-means margin, on another metric's ladder, still holds.
  m.reference_detail->ladder->metrics["p99_pixel_error"] = ladder_of(0.05, 0.9);
  nlohmann::ordered_json unconverged = m;
  add_claim_verdicts(unconverged);
  EXPECT_TRUE(not_converged(verdict_of(unconverged, "tail error"))) << verdict_of(unconverged, "tail error");
  EXPECT_NE(verdict_of(unconverged, "tail error").find("(1 + 1) x 0.45 = 0.9 >= distance 0.399"), std::string::npos)
      << verdict_of(unconverged, "tail error");
  EXPECT_EQ(verdict_of(unconverged, "k-means margin, kmeans_3d"), "holds");
  EXPECT_TRUE(claim_of(unconverged, "tail error").at("reference_margin").is_number());

  // A converged ladder, but against the stride-2 rung modified is no better than Tok15: the two
  // rungs disagree, so the reference does not decide.
  m.reference_detail->ladder->metrics["p99_pixel_error"] = ladder_of(0.001, 0.5);
  m.frames_static->second_rung[kMod]["p99_pixel_error"] = m.frames_static->second_rung[kTok]["p99_pixel_error"];
  nlohmann::ordered_json disagree = m;
  add_claim_verdicts(disagree);
  EXPECT_TRUE(not_converged(verdict_of(disagree, "tail error"))) << verdict_of(disagree, "tail error");
  EXPECT_NE(verdict_of(disagree, "tail error").find("holds against the reference, inconclusive against its stride-2"),
            std::string::npos)
      << verdict_of(disagree, "tail error");
  EXPECT_EQ(claim_of(disagree, "tail error").at("second_rung").at("verdict"), "inconclusive");

  // No stride-2 series: not decided either.
  m.frames_static->second_rung.clear();
  nlohmann::ordered_json no_second = m;
  add_claim_verdicts(no_second);
  EXPECT_TRUE(not_converged(verdict_of(no_second, "tail error")));
  EXPECT_EQ(claim_of(no_second, "tail error").at("second_rung").at("verdict"), "not measured");

  // The worst frame must agree with the interval.
  for (const std::string& g : {kTok, kMod, kKm3})
    for (const char* metric : {"p99_pixel_error", "relative_rmse"})
      if (m.frames_static->generators[g].contains(metric))
        m.frames_static->second_rung[g][metric] = m.frames_static->generators[g][metric];
  mod["p99_pixel_error"][3] = 10.0;
  nlohmann::ordered_json worst = m;
  add_claim_verdicts(worst);
  EXPECT_NE(verdict_of(worst, "tail error"), "holds");
}

// A schema-5 document has no ladder: the reference-decided verdicts it carries are kept as written,
// not judged again, and where it carries none, nothing is decided.
TEST(QualityClaims, WithoutALadderTheWrittenReferenceVerdictsStand) {
  QualityModel m = minimal_model();
  m.schema_version = 5;
  m.reference_detail->ladder.reset();
  m.frames_static->generators[kTok]["p99_pixel_error"] = frames_of(2.0, 1.0);
  m.frames_static->generators[kMod]["p99_pixel_error"] = frames_of(2.0, 0.8);
  m.frames_static->generators[kTok]["light_view_max_over_mean"] = frames_of(20.0, 1.0);
  m.frames_static->generators[kMod]["light_view_max_over_mean"] = frames_of(20.0, 0.5);
  nlohmann::ordered_json fresh = m;
  add_claim_verdicts(fresh);
  EXPECT_EQ(verdict_of(fresh, "tail error"), "reference not converged (no reference ladder)");
  EXPECT_EQ(verdict_of(fresh, "light_view: too-bright"), "holds");
  // A document written with a verdict of its own rule keeps it; the other claims are judged again.
  nlohmann::ordered_json written = fresh;
  for (auto& c : written.at("claims")) {
    if (c.at("measure").get<std::string>().rfind("tail error", 0) == 0) c["verdict"] = "holds";
    if (c.at("measure").get<std::string>().rfind("light_view: too-bright", 0) == 0) c["verdict"] = "does not hold";
  }
  add_claim_verdicts(written);
  EXPECT_EQ(verdict_of(written, "tail error"), "holds");
  EXPECT_EQ(verdict_of(written, "light_view: too-bright"), "holds");
}

// The ladder of DESIGN.md §11a from its successive differences, coarsest pair first.
TEST(QualityReferenceRule, TheRateComesFromThreeSuccessiveDifferences) {
  const ReferenceLadderMetric halving = reference_ladder_metric({0.08, 0.04, 0.02});
  EXPECT_EQ(halving.ratios, (std::vector<double>{0.5, 0.5}));
  EXPECT_DOUBLE_EQ(halving.rate, 0.5);
  EXPECT_DOUBLE_EQ(halving.remaining, 0.02);  // 0.02 x 0.5 / (1 - 0.5)
  // Unequal ratios: their geometric mean, sqrt(e_2 / e_8), not their arithmetic mean.
  const ReferenceLadderMetric uneven = reference_ladder_metric({0.1, 0.08, 0.02});
  ASSERT_EQ(uneven.ratios.size(), 2u);
  EXPECT_DOUBLE_EQ(uneven.ratios[0], 0.8);
  EXPECT_DOUBLE_EQ(uneven.ratios[1], 0.25);
  EXPECT_NEAR(uneven.rate, std::sqrt(0.2), 1e-15);
  EXPECT_NEAR(uneven.remaining, 0.02 * std::sqrt(0.2) / (1 - std::sqrt(0.2)), 1e-15);
  // 0.9 per rung: eps_inf is 9 times the own error.
  EXPECT_NEAR(ladder_of(0.02, 0.9).remaining, 0.18, 1e-12);
  // Fewer rungs: two differences give the one ratio; one gives no rate.
  EXPECT_DOUBLE_EQ(reference_ladder_metric({0.04, 0.01}).rate, 0.25);
  const ReferenceLadderMetric one = reference_ladder_metric({0.02});
  EXPECT_TRUE(one.ratios.empty());
  EXPECT_TRUE(std::isnan(one.rate));
  EXPECT_TRUE(std::isinf(one.remaining));
  // Not converging: rate 1 or more, or a NaN, leaves eps_inf infinite.
  EXPECT_TRUE(std::isinf(reference_ladder_metric({0.02, 0.02, 0.02}).remaining));
  EXPECT_TRUE(std::isinf(reference_ladder_metric({0.01, 0.02, 0.04}).remaining));
  EXPECT_TRUE(std::isinf(reference_ladder_metric({0.08, std::nan(""), 0.02}).remaining));
}

ClaimVerdict verdict(Outcome outcome) {
  ClaimVerdict v;
  v.outcome = outcome;
  v.rule = "interval below 1";
  return v;
}

// A ratio claim with bound 1, distance 0.1, the same verdict against both rungs.
ReferenceClaim ratio_claim(double distance, Outcome finest = Outcome::kHolds, Outcome second = Outcome::kHolds) {
  ReferenceClaim c;
  c.ratio = true;
  c.bound = 1.0;
  c.distance = distance;
  c.finest = verdict(finest);
  c.second_rung = verdict(second);
  return c;
}

TEST(QualityReferenceRule, AConvergedLadderDecides) {
  const ReferenceLadderMetric ladder = reference_ladder_metric({0.08, 0.04, 0.02});  // eps_inf 0.02
  const ClaimVerdict v = reference_decides(&ladder, ratio_claim(0.1));               // (1 + 1) x 0.02 = 0.04 < 0.1
  EXPECT_TRUE(v.holds()) << v.reason;
  EXPECT_TRUE(v.reason.empty());
  EXPECT_NE(v.rule.find("interval below 1, decided only where (1 + b)"), std::string::npos) << v.rule;
  // The rule decides, it does not judge: a verdict that does not hold on both rungs stays so.
  EXPECT_TRUE(reference_decides(&ladder, ratio_claim(0.1, Outcome::kDoesNotHold, Outcome::kDoesNotHold)).fails());
}

TEST(QualityReferenceRule, ASlowOrDivergentLadderDoesNotDecide) {
  // 0.9 per doubling: eps_inf = 9 x own = 0.18, and (1 + 1) x 0.18 = 0.36 >= 0.1.
  const ReferenceLadderMetric slow = ladder_of(0.02, 0.9);
  const ClaimVerdict v = reference_decides(&slow, ratio_claim(0.1));
  EXPECT_TRUE(v.inconclusive());
  EXPECT_EQ(v.reason,
            "reference not converged (own 0.02, rate 0.9, remaining 0.18: (1 + 1) x 0.18 = 0.36 >= distance 0.1)");
  // Rate 1 or more, a NaN difference: the reference does not converge.
  for (const ReferenceLadderMetric& l :
       {reference_ladder_metric({0.02, 0.02, 0.02}), reference_ladder_metric({0.01, 0.02, 0.04}),
        reference_ladder_metric({0.08, std::nan(""), 0.02})}) {
    const ClaimVerdict d = reference_decides(&l, ratio_claim(10.0));
    EXPECT_TRUE(d.inconclusive());
    EXPECT_EQ(d.reason.rfind("reference not converged (own 0.0", 0), 0u) << d.reason;
    EXPECT_NE(d.reason.find("does not converge"), std::string::npos) << d.reason;
  }
  // A NaN distance, one difference (no rate), no ladder at all.
  const ReferenceLadderMetric fast = reference_ladder_metric({0.08, 0.04, 0.02});
  EXPECT_TRUE(reference_decides(&fast, ratio_claim(std::nan(""))).inconclusive());
  const ReferenceLadderMetric one = reference_ladder_metric({0.001});
  EXPECT_EQ(reference_decides(&one, ratio_claim(10.0)).reason,
            "reference not converged (no rate: 1 successive difference(s) of the rungs, two needed)");
  EXPECT_EQ(reference_decides(nullptr, ratio_claim(10.0)).reason, "reference not converged (no reference ladder)");
}

TEST(QualityReferenceRule, TheEdgeAndTheFactorOfADifference) {
  const ReferenceLadderMetric ladder = reference_ladder_metric({0.08, 0.04, 0.02});  // eps_inf 0.02
  // A distance of exactly (1 + b) eps_inf is not decided (the margin must be below it).
  const double edge = reference_margin(ladder, ratio_claim(0.0));
  EXPECT_DOUBLE_EQ(edge, 0.04);
  EXPECT_TRUE(reference_decides(&ladder, ratio_claim(edge)).inconclusive());
  EXPECT_TRUE(reference_decides(&ladder, ratio_claim(std::nextafter(edge, 1.0))).holds());
  // The bound scales a ratio's margin: b = 5 gives 6 x 0.02 = 0.12 ...
  ReferenceClaim wide = ratio_claim(0.05);
  wide.bound = 5.0;
  EXPECT_DOUBLE_EQ(reference_margin(ladder, wide), 0.12);
  EXPECT_TRUE(reference_decides(&ladder, wide).inconclusive());
  // ... but not a difference's, whose margin is 2 eps_inf = 0.04 < 0.05.
  wide.ratio = false;
  EXPECT_DOUBLE_EQ(reference_margin(ladder, wide), 0.04);
  EXPECT_TRUE(reference_decides(&ladder, wide).holds());
}

TEST(QualityReferenceRule, VerdictsThatDifferBetweenTheRungsDoNotDecide) {
  const ReferenceLadderMetric ladder = reference_ladder_metric({0.08, 0.04, 0.02});
  const ClaimVerdict v = reference_decides(&ladder, ratio_claim(0.1, Outcome::kHolds, Outcome::kInconclusive));
  EXPECT_TRUE(v.inconclusive());
  EXPECT_EQ(v.reason,
            "reference not converged (the verdicts differ: holds against the reference, inconclusive against its "
            "stride-2 rung)");
  EXPECT_TRUE(reference_decides(&ladder, ratio_claim(0.1, Outcome::kDoesNotHold, Outcome::kHolds)).inconclusive());
  ReferenceClaim unmeasured = ratio_claim(0.1);
  unmeasured.second_rung.reset();
  EXPECT_EQ(reference_decides(&ladder, unmeasured).reason,
            "reference not converged (no verdict against the stride-2 rung)");
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
      row.per_frame_second_rung = {{"relative_rmse", frames_of(error[i], 1.02)}};
      rows.push_back(row);
    }
    return rows;
  };
  m.k_sweep = {{kMod, sweep(0.35)}, {kTok, sweep(0.2)}};  // Tok15's error falls at the last step
  nlohmann::ordered_json doc = m;
  add_claim_verdicts(doc);
  EXPECT_EQ(verdict_of(doc, "K sweep, fis_modified"), "holds");
  EXPECT_EQ(verdict_of(doc, "K sweep, fis_tok15"), "does not hold");
  // Each error step is decided by the reference's rule: without its stride-2 rung, none is.
  for (auto& [generator, rows] : m.k_sweep)
    for (KSweepRow& row : rows) row.per_frame_second_rung.clear();
  nlohmann::ordered_json unranked = m;
  add_claim_verdicts(unranked);
  EXPECT_EQ(verdict_of(unranked, "K sweep, fis_modified"), "reference not converged at some step");
  EXPECT_EQ(verdict_of(unranked, "K sweep, fis_tok15"), "reference not converged at some step");
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
