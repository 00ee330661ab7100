// The quality claims' verdicts (DESIGN.md §11a.1, quality/quality_claims.hpp) on made-up per-frame
// series whose answer is known: a clear reduction holds, a clear increase does not hold, a series
// that straddles the bound is inconclusive; and the reference's rule (DESIGN.md §11a *Rule*,
// quality/quality_reference.hpp) on made-up ladders: a claim on an error against the reference is
// "reference not converged" unless its interval, widened by how far the claim may still move as
// the reference's RSM side doubles, gives the same verdict, and so does the stride-2 rung.
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
  m.schema_version = 7;
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
  // Against every coarser rung the same frames, a little higher: the claims do not move.
  const auto scaled_rungs = [&](double factor) {
    for (const std::string& g : {kTok, kMod, kKm3})
      for (const char* metric : {"p99_pixel_error", "relative_rmse"})
        if (m.frames_static->generators[g].contains(metric)) {
          std::vector<double>& second = m.frames_static->second_rung[g][metric];
          second.clear();
          for (double v : m.frames_static->generators[g][metric]) second.push_back(factor * v);
        }
  };
  scaled_rungs(1.01);
  nlohmann::ordered_json converged = m;
  add_claim_verdicts(converged);
  EXPECT_EQ(verdict_of(converged, "tail error"), "holds");
  EXPECT_EQ(verdict_of(converged, "k-means margin, kmeans_3d"), "holds");
  // The claim keeps what the rule read: the ladder's own error, rate and eps_inf, the statistic per
  // rung, its remaining movement, the widened interval, and the second rung's verdict.
  const auto tail = claim_of(converged, "tail error");
  EXPECT_EQ(tail.at("reference_metric"), "p99_pixel_error");
  EXPECT_NEAR(tail.at("reference_own_error").get<double>(), 0.001, 1e-15);
  EXPECT_NEAR(tail.at("reference_rate").get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(tail.at("reference_remaining_error").get<double>(), 0.001, 1e-12);
  ASSERT_EQ(tail.at("rung_estimates").size(), 2u);
  EXPECT_NEAR(tail.at("rung_estimates")[0].get<double>(), 0.8, 1e-12);
  EXPECT_NEAR(tail.at("rung_estimates")[1].get<double>(), 0.8, 1e-12);
  EXPECT_NEAR(tail.at("reference_movement").get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(tail.at("widened_interval")[1].get<double>(), tail.at("interval")[1].get<double>(), 1e-12);
  EXPECT_EQ(tail.at("second_rung").at("verdict"), "holds");
  EXPECT_LT(tail.at("second_rung").at("interval")[1].get<double>(), 1.0);
  EXPECT_FALSE(tail.contains("reference_margin"));

  // Against the stride-2 rung modified's tail is 15 % higher: the ratio moves 0.8 -> 0.911. On a
  // ladder of rate 0.5 the movement 0.111 leaves the widened interval below 1; at 0.9 (9 x 0.111)
  // it reaches 1. The k-means margin, on another metric's ladder, still holds.
  for (double& v : m.frames_static->second_rung[kMod]["p99_pixel_error"]) v *= 1.15;
  nlohmann::ordered_json moved = m;
  add_claim_verdicts(moved);
  EXPECT_EQ(verdict_of(moved, "tail error"), "holds");
  m.reference_detail->ladder->metrics["p99_pixel_error"] = ladder_of(0.05, 0.9);
  nlohmann::ordered_json unconverged = m;
  add_claim_verdicts(unconverged);
  EXPECT_TRUE(not_converged(verdict_of(unconverged, "tail error"))) << verdict_of(unconverged, "tail error");
  EXPECT_NE(verdict_of(unconverged, "tail error").find("over the rungs, rate 0.9, remaining 1"), std::string::npos)
      << verdict_of(unconverged, "tail error");
  EXPECT_EQ(verdict_of(unconverged, "k-means margin, kmeans_3d"), "holds");

  // The coarser rungs count too: the same claim, still at rate 0.5 and unmoved at stride 2, but 60 %
  // higher for modified at stride 4, is not decided ((1.267 - 0.8) x 0.5 = 0.233 of movement).
  m.reference_detail->ladder->metrics["p99_pixel_error"] = ladder_of(0.001, 0.5);
  scaled_rungs(1.01);
  m.frames_static->coarse_rung_strides = {8, 4};
  for (const std::string& g : {kTok, kMod, kKm3}) {
    m.frames_static->coarse_rungs[g] = {m.frames_static->second_rung[g], m.frames_static->second_rung[g]};
    if (g == kMod)
      for (double& v : m.frames_static->coarse_rungs[g][1]["p99_pixel_error"]) v *= 1.6;
  }
  nlohmann::ordered_json coarse = m;
  add_claim_verdicts(coarse);
  EXPECT_TRUE(not_converged(verdict_of(coarse, "tail error"))) << verdict_of(coarse, "tail error");
  EXPECT_EQ(claim_of(coarse, "tail error").at("rung_estimates").size(), 4u);
  EXPECT_EQ(verdict_of(coarse, "k-means margin, kmeans_3d"), "holds");
  // ... and read back, the document keeps the coarser rungs.
  const QualityModel back = quality_model_from_json(coarse, "made up");
  EXPECT_EQ(back.frames_static->coarse_rung_strides, (std::vector<uint32_t>{8, 4}));
  EXPECT_EQ(back.frames_static->coarse_rungs.at(kMod).size(), 2u);
  m.frames_static->coarse_rungs.clear();
  m.frames_static->coarse_rung_strides.clear();

  // Against the stride-2 rung modified is no better than Tok15: the two rungs disagree, so the
  // reference does not decide.
  m.frames_static->second_rung[kMod]["p99_pixel_error"] = m.frames_static->second_rung[kTok]["p99_pixel_error"];
  nlohmann::ordered_json disagree = m;
  add_claim_verdicts(disagree);
  EXPECT_TRUE(not_converged(verdict_of(disagree, "tail error"))) << verdict_of(disagree, "tail error");
  EXPECT_TRUE(not_converged(verdict_of(disagree, "tail error")));

  // No stride-2 series: not decided either.
  m.frames_static->second_rung.clear();
  nlohmann::ordered_json no_second = m;
  add_claim_verdicts(no_second);
  EXPECT_EQ(verdict_of(no_second, "tail error"), "reference not converged (no estimate against the stride-2 rung)");
  EXPECT_EQ(claim_of(no_second, "tail error").at("second_rung").at("verdict"), "not measured");

  // The worst frame must agree with the interval.
  scaled_rungs(1.0);
  mod["p99_pixel_error"][3] = 10.0;
  nlohmann::ordered_json worst = m;
  add_claim_verdicts(worst);
  EXPECT_NE(verdict_of(worst, "tail error"), "holds");
}

// A document before schema 7 was judged by an earlier rule: the reference-decided verdicts it
// carries are kept as written, not judged again; without a ladder (schema 5) and without written
// verdicts, nothing is decided.
TEST(QualityClaims, ADocumentOfAnEarlierRuleKeepsItsReferenceVerdicts) {
  QualityModel m = minimal_model();
  m.schema_version = 6;
  m.frames_static->generators[kTok]["p99_pixel_error"] = frames_of(2.0, 1.0);
  m.frames_static->generators[kMod]["p99_pixel_error"] = frames_of(2.0, 0.8);
  for (const std::string& g : {kTok, kMod})
    m.frames_static->second_rung[g]["p99_pixel_error"] = m.frames_static->generators[g]["p99_pixel_error"];
  nlohmann::ordered_json written = m;
  add_claim_verdicts(written);
  EXPECT_EQ(verdict_of(written, "tail error"), "holds");
  for (auto& c : written.at("claims"))
    if (c.at("measure").get<std::string>().rfind("tail error", 0) == 0) c["verdict"] = "reference not converged (x)";
  add_claim_verdicts(written);
  EXPECT_EQ(verdict_of(written, "tail error"), "reference not converged (x)");
  // Schema 7 judges again.
  m.schema_version = 7;
  nlohmann::ordered_json current = m;
  current["claims"] = written.at("claims");
  add_claim_verdicts(current);
  EXPECT_EQ(verdict_of(current, "tail error"), "holds");
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

// A claim below bound 1 whose interval against the reference is [low, high], with the statistic
// against each rung `estimates` (coarsest first, the reference's last) and the stride-2 verdict.
ReferenceClaim below_one(double low, double high, std::vector<double> estimates,
                         std::optional<Outcome> second = std::nullopt) {
  ReferenceClaim c;
  c.side = ClaimSide::kBelow;
  c.bound = 1.0;
  c.finest = judge_below({low, high}, 1.0);
  c.rung_estimates = std::move(estimates);
  c.second_rung = judge_below({low, high}, 1.0);
  if (second) c.second_rung->outcome = *second;
  return c;
}

TEST(QualityReferenceRule, TheRemainingMovementIsTheLargestExtrapolatedStep) {
  // Steps from the finest: 0.01, 0.02, 0.1; at rate 0.5 weighted 0.01, 0.01, 0.025; the largest,
  // times 0.5 / (1 - 0.5).
  EXPECT_NEAR(reference_movement(0.5, {1.0, 1.1, 1.12, 1.13}), 0.025, 1e-15);
  // Two estimates: the one step's geometric tail.
  EXPECT_NEAR(reference_movement(0.75, {0.9, 0.92}), 0.06, 1e-15);
  // A step the claim did not move: no movement to come.
  EXPECT_EQ(reference_movement(0.5, {0.9, 0.9, 0.9}), 0.0);
  // No rate below 1, fewer than two estimates, an estimate that is not finite: infinite.
  const double nan = std::nan("");
  for (double m : {reference_movement(1.0, {0.9, 0.92}), reference_movement(nan, {0.9, 0.92}),
                   reference_movement(0.5, {0.9}), reference_movement(0.5, {nan, 0.9, 0.92})})
    EXPECT_TRUE(std::isinf(m));
}

TEST(QualityReferenceRule, AClaimThatStaysClearOfTheBoundDecides) {
  const ReferenceLadderMetric ladder = reference_ladder_metric({0.08, 0.04, 0.02});  // rate 0.5
  // Steps 0.04, 0.03, 0.005 (coarsest first): the movement 0.015; [0.785, 0.865] is below 1.
  const ClaimVerdict v = reference_decides(&ladder, below_one(0.80, 0.85, {0.9, 0.86, 0.83, 0.825}));
  EXPECT_TRUE(v.holds()) << v.reason;
  EXPECT_TRUE(v.reason.empty());
  EXPECT_NE(v.rule.find("interval below 1, decided only where the interval widened"), std::string::npos) << v.rule;
  // The rule decides, it does not judge: an interval wholly above the bound stays "does not hold".
  ReferenceClaim above = below_one(1.10, 1.15, {1.2, 1.15, 1.13, 1.125}, Outcome::kDoesNotHold);
  above.finest = judge_below({1.10, 1.15}, 1.0);
  EXPECT_TRUE(reference_decides(&ladder, above).fails());
}

TEST(QualityReferenceRule, AClaimThatMovesAsFarAsTheBoundIsNotDecided) {
  const ReferenceLadderMetric ladder = reference_ladder_metric({0.08, 0.04, 0.02});  // rate 0.5
  // The last step 0.035 alone: [0.915, 1.015] reaches 1.
  const ClaimVerdict v = reference_decides(&ladder, below_one(0.95, 0.98, {0.80, 0.88, 0.93, 0.965}));
  EXPECT_TRUE(v.inconclusive());
  EXPECT_EQ(v.reason.rfind("reference not converged (the claim moved 0.08, 0.05, 0.035 over the rungs, rate 0.5, "
                           "remaining 0.035: the widened interval [0.915, 1.0",
                           0),
            0u)
      << v.reason;
  EXPECT_NE(v.reason.find("] reaches the bound 1)"), std::string::npos) << v.reason;
  // A last step that happens to be tiny does not hide a large earlier one: 0.145 at stride 4 to 2,
  // shrinking by 0.5 to 0.072, widens [0.93, 0.96] past 1.
  EXPECT_TRUE(reference_decides(&ladder, below_one(0.93, 0.96, {0.70, 0.80, 0.9449, 0.945})).inconclusive());
  // The same claim on a faster reference decides: at rate 0.1 the movement is 0.0145.
  const ReferenceLadderMetric fast = reference_ladder_metric({0.2, 0.02, 0.002});
  EXPECT_TRUE(reference_decides(&fast, below_one(0.93, 0.96, {0.70, 0.80, 0.9449, 0.945})).holds());
  // A "does not hold" whose widened interval reaches the bound is not decided either.
  ReferenceClaim above = below_one(1.01, 1.03, {1.3, 1.2, 1.1, 1.02}, Outcome::kDoesNotHold);
  EXPECT_TRUE(reference_decides(&ladder, above).inconclusive());
}

TEST(QualityReferenceRule, ASlowOrDivergentLadderOrAMissingRungDoesNotDecide) {
  // Rate 1 or more, a NaN difference: the reference does not converge.
  for (const ReferenceLadderMetric& l :
       {reference_ladder_metric({0.02, 0.02, 0.02}), reference_ladder_metric({0.01, 0.02, 0.04}),
        reference_ladder_metric({0.08, std::nan(""), 0.02})}) {
    const ClaimVerdict d = reference_decides(&l, below_one(0.5, 0.6, {0.55, 0.55}));
    EXPECT_TRUE(d.inconclusive());
    EXPECT_NE(d.reason.find("does not converge"), std::string::npos) << d.reason;
  }
  const ReferenceLadderMetric fast = reference_ladder_metric({0.08, 0.04, 0.02});
  const ReferenceLadderMetric one = reference_ladder_metric({0.001});
  EXPECT_EQ(reference_decides(&one, below_one(0.5, 0.6, {0.55, 0.55})).reason,
            "reference not converged (no rate: 1 successive difference(s) of the rungs, two needed)");
  EXPECT_EQ(reference_decides(nullptr, below_one(0.5, 0.6, {0.55, 0.55})).reason,
            "reference not converged (no reference ladder)");
  EXPECT_EQ(reference_decides(&fast, below_one(0.5, 0.6, {0.55})).reason,
            "reference not converged (no estimate against the stride-2 rung)");
  ReferenceClaim no_interval = below_one(0.5, 0.6, {0.55, 0.55});
  no_interval.finest.interval.reset();
  EXPECT_EQ(reference_decides(&fast, no_interval).reason,
            "reference not converged (no interval against the reference)");
  // An interval that reaches the bound by itself keeps its own reason.
  ReferenceClaim touching = below_one(0.9, 1.1, {1.0, 1.0});
  touching.finest.reason = "inconclusive: the 95 % interval reaches the bound";
  EXPECT_EQ(reference_decides(&fast, touching).reason, "inconclusive: the 95 % interval reaches the bound");
}

TEST(QualityReferenceRule, VerdictsThatDifferBetweenTheRungsDoNotDecide) {
  const ReferenceLadderMetric ladder = reference_ladder_metric({0.08, 0.04, 0.02});
  const ClaimVerdict v = reference_decides(&ladder, below_one(0.5, 0.6, {0.55, 0.55}, Outcome::kInconclusive));
  EXPECT_TRUE(v.inconclusive());
  EXPECT_EQ(v.reason,
            "reference not converged (the verdicts differ: holds against the reference, inconclusive against its "
            "stride-2 rung)");
  ReferenceClaim unmeasured = below_one(0.5, 0.6, {0.55, 0.55});
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

// Fig. 7 (DESIGN.md §11a.2): per FIS generator, its error over the occluded region above 3D
// k-means's, and within [0.8, 1.25] of 2D k-means's, decided by R_v's own ladder.
TEST(QualityClaims, Fig7JudgesEachFisGeneratorAgainstBothKmeans) {
  QualityModel m = minimal_model();
  m.generators = {kTok, kMod, std::string(kKmeans2d), kKm3};
  m.reference_error[std::string(kKmeans2d)] = {};
  m.flicker_static[std::string(kKmeans2d)] = {0.1, 0.0, 0.0, 32};
  OcclusionMeasure o;
  o.visibility = "visibility ism (made up)";
  o.reference_rsm_stride = 1;
  o.reference_rsm_side = 8;
  o.reference_vpls = 64;
  o.surface_pixels = 1000;
  o.occluded_pixels = 200;
  o.ladder.rsm_strides = {8, 4, 2, 1};
  o.ladder.rsm_sides = {1, 2, 4, 8};
  o.ladder.metrics["relative_rmse"] = ladder_of(0.001, 0.5);
  o.frames.gbuffer_stride = 1;
  o.frames.image = nlohmann::ordered_json::array({16, 8});
  o.frames.reference = "made up";
  const auto set = [&](const std::string& g, double error) {
    o.frames.generators[g]["relative_rmse"] = frames_of(error, 1.0);
    o.frames.second_rung[g]["relative_rmse"] = frames_of(error, 1.01);
  };
  set(kTok, 0.5);  // above 3D k-means (0.3), 1.11 x 2D k-means (0.45): holds, holds
  set(kMod, 0.2);  // below 3D k-means, 0.44 x 2D k-means: does not hold, does not hold
  set(std::string(kKmeans2d), 0.45);
  set(kKm3, 0.3);
  m.occlusion = o;
  nlohmann::ordered_json doc = m;
  add_claim_verdicts(doc);
  EXPECT_EQ(verdict_of(doc, "Fig. 7 world space, fis_tok15"), "holds");
  EXPECT_EQ(verdict_of(doc, "Fig. 7 image space, fis_tok15"), "holds");
  EXPECT_EQ(verdict_of(doc, "Fig. 7 world space, fis_modified"), "does not hold");
  EXPECT_EQ(verdict_of(doc, "Fig. 7 image space, fis_modified"), "does not hold");
  const auto band = claim_of(doc, "Fig. 7 image space, fis_tok15");
  EXPECT_EQ(band.at("claimed_side"), "within");
  EXPECT_EQ(band.at("bound"), 0.8);
  EXPECT_EQ(band.at("bound_high"), 1.25);
  // Read back, the document keeps the measurement.
  const QualityModel back = quality_model_from_json(doc, "made up");
  ASSERT_TRUE(back.occlusion.has_value());
  EXPECT_EQ(back.occlusion->occluded_pixels, 200u);
  EXPECT_EQ(back.occlusion->frames.generators.at(kTok).at("relative_rmse"),
            o.frames.generators.at(kTok).at("relative_rmse"));

  // Tok15's ratio to 2D k-means is 1.3 against the stride-2 rung and 1.11 against R_v: at rate 0.5
  // the movement 0.19 widens the interval past the edge 1.25: not decided.
  m.occlusion->frames.second_rung[kTok]["relative_rmse"] = frames_of(0.45 * 1.3, 1.01);
  nlohmann::ordered_json moved = m;
  add_claim_verdicts(moved);
  EXPECT_TRUE(not_converged(verdict_of(moved, "Fig. 7 image space, fis_tok15")))
      << verdict_of(moved, "Fig. 7 image space, fis_tok15");
  EXPECT_NE(verdict_of(moved, "Fig. 7 image space, fis_tok15").find("reaches the bound of [0.8, 1.25]"),
            std::string::npos);

  // Too few occluded pixels: each Fig. 7 claim is inconclusive and says why.
  m.occlusion->note = "no occluded region: 3 pixel(s) of 1000 in O, fewer than 50 or 1 %";
  nlohmann::ordered_json none = m;
  add_claim_verdicts(none);
  for (const char* claim : {"Fig. 7 world space, fis_tok15", "Fig. 7 image space, fis_modified"})
    EXPECT_EQ(verdict_of(none, claim),
              "inconclusive: no occluded region: 3 pixel(s) of 1000 in O, fewer than 50 or 1 %");
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
