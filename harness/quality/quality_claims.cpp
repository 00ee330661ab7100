#include "harness/quality/quality_claims.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "harness/core/claim_verdict.hpp"
#include "harness/core/generator_ids.hpp"
#include "harness/core/paired_comparison.hpp"
#include "harness/core/sorted_json.hpp"
#include "harness/formats/quality_model.hpp"
#include "harness/quality/quality_reference.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;
using ojson = nlohmann::ordered_json;

const std::string kTok15(kFisTok15), kModified(kFisModified);

// The bounds of DESIGN.md §11a.1, fixed for every scene and device.
constexpr double kReductionBound = 0.99;     // a reduction: mean(mod) / mean(Tok15) below 0.99
constexpr double kExcessBound = -0.02;       // Fig. 1: mean(mod) - mean(Tok15) below -0.02
constexpr double kKmeansMarginBound = 1.10;  // Fig. 5: mean(mod) / mean(k-means) below 1.10

const std::string kFig1Claim =
    "Modified FIS reduces overlaps of and gaps between filtering kernels (Fig. 1) and the too-bright VSGLs they "
    "cause (Fig. 5).";
const std::string kFlickerClaim =
    "Using our kernel size, flickering artifacts are reduced significantly for a high-frequency PDF.";
const std::string kFig5Claim =
    "The previous method produces too bright of a VSGL with low probability; our method does not produce such an "
    "error (Fig. 5).";
const std::string kFig6Claim = "K > 1 trades illumination detail for temporal coherence (Fig. 6).";

std::string num(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

enum class Quantity { kRatio, kDifference };

// What a claim on an error against the reference is decided by (DESIGN.md §11a *Rule*): the
// metric's ladder, and the same two series against every coarser rung of it.
struct ReferenceSide {
  using Pair = std::pair<std::span<const double>, std::span<const double>>;
  std::string metric;
  const ReferenceLadderMetric* ladder = nullptr;  // none in a schema-5 document
  std::vector<Pair> coarse;                       // a and b against each rung coarser than stride 2, coarsest first
  std::optional<Pair> second;                     // a and b against the stride-2 rung; none: not measured
};

// Series a against series b, paired by frame, against `bound` on the claimed side.
struct Comparison {
  std::string a_label, b_label;
  std::span<const double> a, b;
  Quantity quantity = Quantity::kRatio;
  bool below = true;  // the claim: the quantity lies below the bound (else above)
  double bound = 1.0;
  std::optional<ReferenceSide> reference;  // set for a claim the reference decides
  // A band instead: the quantity lies strictly inside (bound, bound_high); `below` is then unused.
  bool within = false;
  double bound_high = 0;

  ClaimSide side() const { return within ? ClaimSide::kWithin : below ? ClaimSide::kBelow : ClaimSide::kAbove; }
  std::string side_text() const {
    return within ? "inside [" + num(bound) + ", " + num(bound_high) + "]"
                  : std::string(below ? "below " : "above ") + num(bound);
  }
};

// A comparison's verdict and the numbers it was judged on (the claim's `measured`).
struct JudgedComparison {
  ClaimVerdict verdict;
  ojson measured;
  double estimate = 0;  // mean(a) / mean(b) or mean(a) - mean(b)
};

const std::string kNotConverged = "reference not converged";

ClaimVerdict inconclusive(std::string rule, std::string reason) {
  ClaimVerdict v;
  v.outcome = Outcome::kInconclusive;
  v.rule = std::move(rule);
  v.reason = std::move(reason);
  return v;
}

// A ladder value for the document: null where it is not finite (DESIGN.md §11a).
ojson finite_or_null(double v) { return std::isfinite(v) ? ojson(v) : ojson(nullptr); }

// The interval verdict of a against b alone, without the reference's rule.
JudgedComparison judge_interval(const Comparison& c, std::span<const double> a, std::span<const double> b) {
  const PairedBootstrap boot = paired_bootstrap(a, b);
  const SignTest sign = sign_test(a, b);
  JudgedComparison j;
  const bool ratio = c.quantity == Quantity::kRatio;
  j.measured = ojson{{c.a_label, boot.mean_a}, {c.b_label, boot.mean_b}, {"frames", boot.frames}};
  j.measured["quantity"] = ratio ? "mean(a) / mean(b)" : "mean(a) - mean(b)";
  j.measured["bound"] = c.bound;
  if (c.within) j.measured["bound_high"] = c.bound_high;
  j.measured["claimed_side"] = c.within ? "within" : c.below ? "below" : "above";
  j.measured["sign_test"] = ojson{
      {"a_below", sign.a_below}, {"a_above", sign.a_above}, {"ties", sign.ties}, {"p_two_sided", sign.p_two_sided}};
  j.measured["bootstrap"] = ojson{{"resamples", boot.resamples}, {"confidence", boot.confidence}, {"seed", boot.seed}};
  j.estimate = ratio ? boot.mean_a / boot.mean_b : boot.difference;
  if (ratio && !boot.ratio_interval) {
    j.verdict =
        inconclusive("interval " + c.side_text(), std::string(kInconclusivePrefix) + ": a frame of " + c.b_label +
                                                      " is not positive, so the ratio has no interval");
    return j;
  }
  const PercentileInterval iv = ratio ? *boot.ratio_interval : boot.difference_interval;
  j.measured["estimate"] = ratio ? *boot.ratio : boot.difference;
  j.measured["interval"] = ojson::array({iv.low, iv.high});
  j.verdict = judge_side(c.side(), {iv.low, iv.high}, c.bound, c.bound_high);
  if (j.verdict.inconclusive())
    j.verdict.reason =
        std::string(kInconclusivePrefix) + ": the 95 % interval [" + num(iv.low) + ", " + num(iv.high) + "] reaches " +
        (c.within ? "an edge of [" + num(c.bound) + ", " + num(c.bound_high) + "]" : "the bound " + num(c.bound));
  return j;
}

// The claim's statistic of a against b (no interval): what each coarser rung contributes.
double estimate_of(const Comparison& c, std::span<const double> a, std::span<const double> b) {
  double sa = 0, sb = 0;
  for (double v : a) sa += v;
  for (double v : b) sb += v;
  return c.quantity == Quantity::kRatio ? sa / sb : (sa - sb) / static_cast<double>(a.size());
}

JudgedComparison judge(const Comparison& c) {
  JudgedComparison j = judge_interval(c, c.a, c.b);
  if (!c.reference) return j;
  // A claim the reference decides (DESIGN.md §11a *Rule*): its statistic against every rung.
  const ReferenceSide& ref = *c.reference;
  ReferenceClaim claim;
  claim.side = c.side();
  claim.bound = c.bound;
  claim.bound_high = c.bound_high;
  claim.finest = j.verdict;
  ojson second{{"verdict", "not measured"}};
  if (ref.second) {
    for (const auto& [a, b] : ref.coarse) claim.rung_estimates.push_back(estimate_of(c, a, b));
    const JudgedComparison s = judge_interval(c, ref.second->first, ref.second->second);
    claim.second_rung = s.verdict;
    claim.rung_estimates.push_back(s.estimate);
    second = ojson{{"verdict", std::string(outcome_text(s.verdict.outcome))}};
    if (s.measured.contains("interval")) {
      second["estimate"] = s.measured.at("estimate");
      second["interval"] = s.measured.at("interval");
    }
  }
  claim.rung_estimates.push_back(j.estimate);
  j.measured["reference_metric"] = ref.metric;
  j.measured["second_rung"] = second;
  j.measured["rung_estimates"] = claim.rung_estimates;
  if (ref.ladder) {
    if (!ref.ladder->differences.empty()) j.measured["reference_own_error"] = ref.ladder->differences.back();
    j.measured["reference_rate"] = finite_or_null(ref.ladder->rate);
    j.measured["reference_remaining_error"] = finite_or_null(ref.ladder->remaining);
    const double movement = reference_movement(ref.ladder->rate, claim.rung_estimates);
    j.measured["reference_movement"] = finite_or_null(movement);
    if (std::isfinite(movement) && j.verdict.interval)
      j.measured["widened_interval"] =
          ojson::array({j.verdict.interval->low - movement, j.verdict.interval->high + movement});
  }
  j.verdict = reference_decides(ref.ladder, claim);
  return j;
}

Claim make_claim(const std::string& text, const std::string& source, const std::string& measure, JudgedComparison j) {
  Claim c;
  c.text = text;
  c.source = source;
  c.criterion = measure;
  c.measured = std::move(j.measured);
  c.verdict = std::move(j.verdict);
  return c;
}

// A claim this document does not measure: no verdict, and the note says why.
Claim unmeasured_claim(const std::string& text, const std::string& source, const std::string& measure,
                       const std::string& note) {
  Claim c;
  c.text = text;
  c.source = source;
  c.criterion = measure;
  c.measured = ojson::object();
  c.note = note;
  return c;
}

const std::vector<double>* series_of(const FrameErrors& f, const std::string& generator, const std::string& series) {
  const auto g = f.generators.find(generator);
  if (g == f.generators.end()) return nullptr;
  const auto s = g->second.find(series);
  return s == g->second.end() ? nullptr : &s->second;
}

const std::vector<double>* find_series(const FrameSeries& series, const std::string& name) {
  const auto s = series.find(name);
  return s == series.end() ? nullptr : &s->second;
}

// The reference side of a claim on `metric` (DESIGN.md §11a *Rule*): the document's ladder of that
// metric, if any, and the two series against the coarser rungs, if measured (each list coarsest
// first, the stride-2 rung last; a and b of the same length).
ReferenceSide reference_side(const ReferenceLadder* ladder, const std::string& metric,
                             const std::vector<const FrameSeries*>& a_rungs,
                             const std::vector<const FrameSeries*>& b_rungs) {
  ReferenceSide r;
  r.metric = metric;
  if (ladder) {
    const auto it = ladder->metrics.find(metric);
    if (it != ladder->metrics.end()) r.ladder = &it->second;
  }
  if (a_rungs.empty() || a_rungs.size() != b_rungs.size()) return r;
  std::vector<ReferenceSide::Pair> pairs;
  for (std::size_t i = 0; i < a_rungs.size(); ++i) {
    const auto* a = a_rungs[i] ? find_series(*a_rungs[i], metric) : nullptr;
    const auto* b = b_rungs[i] ? find_series(*b_rungs[i], metric) : nullptr;
    if (!a || !b) return r;
    pairs.emplace_back(*a, *b);
  }
  r.second = pairs.back();
  pairs.pop_back();
  r.coarse = std::move(pairs);
  return r;
}

// The same with the quality reference's ladder (schema 6 and later; none in a schema-5 document).
ReferenceSide reference_side(const QualityModel& m, const std::string& metric,
                             const std::vector<const FrameSeries*>& a_rungs,
                             const std::vector<const FrameSeries*>& b_rungs) {
  const ReferenceLadder* ladder =
      m.reference_detail && m.reference_detail->ladder ? &*m.reference_detail->ladder : nullptr;
  return reference_side(ladder, metric, a_rungs, b_rungs);
}

// A generator's static series against the rungs coarser than the reference, coarsest first, the
// stride-2 rung last; empty where the stride-2 rung was not measured.
std::vector<const FrameSeries*> rungs_of(const FrameErrors& f, const std::string& generator) {
  const auto second = f.second_rung.find(generator);
  if (second == f.second_rung.end()) return {};
  std::vector<const FrameSeries*> rungs;
  if (const auto coarse = f.coarse_rungs.find(generator); coarse != f.coarse_rungs.end())
    for (const FrameSeries& s : coarse->second) rungs.push_back(&s);
  rungs.push_back(&second->second);
  return rungs;
}

// modified against Tok15 on one static series.
void add_fis_claim(std::vector<Claim>& claims, const FrameErrors& f, const std::string& text, const std::string& source,
                   const std::string& measure, const std::string& series, Quantity quantity, double bound) {
  const auto* mod = series_of(f, kModified, series);
  const auto* tok = series_of(f, kTok15, series);
  if (!mod || !tok) return;
  claims.push_back(
      make_claim(text, source, measure, judge({kModified, kTok15, *mod, *tok, quantity, true, bound, {}})));
}

void add_static_claims(std::vector<Claim>& claims, const QualityModel& m) {
  const FrameErrors& f = *m.frames_static;
  for (const std::string& view : {std::string("light_view"), std::string("camera_view")}) {
    add_fis_claim(claims, f, kFig1Claim, "paper_tables.json claims[3]; DESIGN.md §11a.1",
                  view + ": coverage excess over the lattice floor (count-weighted, Eq. 3 footprint), per frame",
                  view + "_coverage_excess", Quantity::kDifference, kExcessBound);
    add_fis_claim(claims, f, kFig1Claim, "paper §3 (Eq. 2-3)",
                  view + ": stdev of the kernel PDF mass a(l)p_bar / (K/N), per frame", view + "_mass_stdev",
                  Quantity::kRatio, kReductionBound);
    add_fis_claim(claims, f, kFig1Claim, "paper_tables.json claims[3]",
                  view + ": too-bright VSGLs, max Phi_i / mean Phi, per frame", view + "_max_over_mean",
                  Quantity::kRatio, kReductionBound);
  }
  add_fis_claim(claims, f, kFlickerClaim, "paper §1, §4 (text)",
                "static flicker: per-frame lattice offset, frame deviation from the pixels' temporal mean",
                "flicker_deviation", Quantity::kRatio, kReductionBound);
  // Fig. 5's tail: the per-frame 99th percentile pixel error, and the worst frame of each.
  const auto* mod = series_of(f, kModified, "p99_pixel_error");
  const auto* tok = series_of(f, kTok15, "p99_pixel_error");
  if (mod && tok) {
    JudgedComparison j = judge({kModified, kTok15, *mod, *tok, Quantity::kRatio, true, 1.0,
                                reference_side(m, "p99_pixel_error", rungs_of(f, kModified), rungs_of(f, kTok15))});
    const double worst_mod = *std::max_element(mod->begin(), mod->end());
    const double worst_tok = *std::max_element(tok->begin(), tok->end());
    j.measured["worst_frame"] = ojson{{kModified, worst_mod}, {kTok15, worst_tok}};
    j.verdict.rule += ", and modified's worst frame below Tok15's";
    if (j.verdict.holds() && !(worst_mod < worst_tok)) {
      j.verdict.outcome = Outcome::kInconclusive;
      j.verdict.reason =
          std::string(kInconclusivePrefix) + ": the interval holds, but modified's worst frame is not below Tok15's";
    }
    claims.push_back(make_claim(kFig5Claim, "paper §4, Fig. 5; DESIGN.md §11a.1",
                                "tail error: 99th percentile pixel error against the reference, per frame, and the "
                                "worst frame",
                                std::move(j)));
  }
  for (const std::string& kmeans : {std::string(kKmeans2d), std::string(kKmeans3d)}) {
    const auto* km = series_of(f, kmeans, "relative_rmse");
    const auto* md = series_of(f, kModified, "relative_rmse");
    if (!km || !md) continue;
    claims.push_back(
        make_claim(kFig5Claim, "paper Fig. 5 (modified beside k-means); DESIGN.md §11a.1",
                   "k-means margin, " + kmeans +
                       ": relative RMSE against the reference, per frame, "
                       "modified within 10 % of k-means",
                   judge({kModified, kmeans, *md, *km, Quantity::kRatio, true, kKmeansMarginBound,
                          reference_side(m, "relative_rmse", rungs_of(f, kModified), rungs_of(f, kmeans))})));
  }
}

void add_animated_claim(std::vector<Claim>& claims, const QualityModel& m) {
  if (!m.frames_animated) return;
  add_fis_claim(claims, *m.frames_animated, kFlickerClaim, "paper §1, §4 (text)",
                "animated flicker: frame deviation of the error against the per-frame reference",
                "error_flicker_deviation", Quantity::kRatio, kReductionBound);
}

const std::string kFig7Claim =
    "FIS-based approaches ignore the difference of world space positions, so they blur some indirect illumination "
    "occluded by the columns, similar to the k-means-based approach using image space (Fig. 7).";

// The band "blurs it as 2D k-means does" (DESIGN.md §11a.2): a factor 1.25 either way.
constexpr double kImageSpaceLow = 0.8, kImageSpaceHigh = 1.25;

// Fig. 7 (DESIGN.md §11a.2), per FIS generator: its error over the occluded region above 3D
// k-means's, and within [0.8, 1.25] of 2D k-means's, decided by R_v's ladder.
void add_occlusion_claims(std::vector<Claim>& claims, const QualityModel& m) {
  if (!m.occlusion) return;
  const OcclusionMeasure& o = *m.occlusion;
  const std::string source = "paper Fig. 7, §5; DESIGN.md §11a.2";
  for (const std::string& gen : {kTok15, kModified}) {
    const std::string world = "Fig. 7 world space, " + gen +
                              ": relative RMSE over the occluded region against the exact-visibility reference, per "
                              "frame, above 3D k-means's";
    const std::string image = "Fig. 7 image space, " + gen +
                              ": relative RMSE over the occluded region, per frame, within [0.8, 1.25] of 2D "
                              "k-means's";
    if (!o.note.empty()) {
      for (const std::string& measure : {world, image}) {
        JudgedComparison j;
        j.measured = ojson::object();
        j.verdict = inconclusive("see DESIGN.md §11a.2", std::string(kInconclusivePrefix) + ": " + o.note);
        claims.push_back(make_claim(kFig7Claim, source, measure, std::move(j)));
      }
      continue;
    }
    const auto* g = series_of(o.frames, gen, "relative_rmse");
    const auto* km3 = series_of(o.frames, std::string(kKmeans3d), "relative_rmse");
    const auto* km2 = series_of(o.frames, std::string(kKmeans2d), "relative_rmse");
    if (g && km3)
      claims.push_back(make_claim(kFig7Claim, source, world,
                                  judge({gen, std::string(kKmeans3d), *g, *km3, Quantity::kRatio, false, 1.0,
                                         reference_side(&o.ladder, "relative_rmse", rungs_of(o.frames, gen),
                                                        rungs_of(o.frames, std::string(kKmeans3d)))})));
    if (g && km2) {
      Comparison c{gen,
                   std::string(kKmeans2d),
                   *g,
                   *km2,
                   Quantity::kRatio,
                   true,
                   kImageSpaceLow,
                   reference_side(&o.ladder, "relative_rmse", rungs_of(o.frames, gen),
                                  rungs_of(o.frames, std::string(kKmeans2d)))};
      c.within = true;
      c.bound_high = kImageSpaceHigh;
      claims.push_back(make_claim(kFig7Claim, source, image, judge(c)));
    }
  }
}

// Fig. 6: at every step of the K sweep flicker falls and the error grows; an intersection-union
// test (DESIGN.md §11a.1).
void add_k_sweep_claims(std::vector<Claim>& claims, const QualityModel& m) {
  for (const std::string& gen : {kModified, kTok15}) {
    const auto it = std::find_if(m.k_sweep.begin(), m.k_sweep.end(), [&](const auto& s) { return s.first == gen; });
    if (it == m.k_sweep.end() || it->second.size() < 2) continue;
    const std::vector<KSweepRow>& rows = it->second;
    const bool per_frame = std::all_of(rows.begin(), rows.end(), [](const KSweepRow& r) {
      return r.per_frame.contains("flicker_deviation") && r.per_frame.contains("relative_rmse");
    });
    if (!per_frame) continue;
    ojson steps = ojson::array();
    bool all_hold = true, any_fails = false, unconverged = false;
    std::string ks;
    for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
      const KSweepRow &lo = rows[i], &hi = rows[i + 1];
      const std::string a = "K=" + num(hi.K), b = "K=" + num(lo.K);
      const JudgedComparison flicker = judge({a,
                                              b,
                                              hi.per_frame.at("flicker_deviation"),
                                              lo.per_frame.at("flicker_deviation"),
                                              Quantity::kRatio,
                                              true,
                                              1.0,
                                              {}});
      const auto rungs = [](const KSweepRow& row) {
        std::vector<const FrameSeries*> list;
        if (row.per_frame_second_rung.empty()) return list;
        for (const FrameSeries& s : row.per_frame_coarse_rungs) list.push_back(&s);
        list.push_back(&row.per_frame_second_rung);
        return list;
      };
      const JudgedComparison error =
          judge({a, b, hi.per_frame.at("relative_rmse"), lo.per_frame.at("relative_rmse"), Quantity::kRatio, false, 1.0,
                 reference_side(m, "relative_rmse", rungs(hi), rungs(lo))});
      for (const ClaimVerdict* v : {&flicker.verdict, &error.verdict}) {
        all_hold = all_hold && v->holds();
        any_fails = any_fails || v->fails();
        unconverged = unconverged || (v->inconclusive() && v->reason.rfind(kNotConverged, 0) == 0);
      }
      steps.push_back(
          ojson{{"from_K", lo.K}, {"to_K", hi.K}, {"flicker", flicker.measured}, {"error", error.measured}});
      ks += (ks.empty() ? num(lo.K) : "") + ", " + num(hi.K);
    }
    // An intersection-union test: every step's verdict must hold (DESIGN.md §11a.1).
    JudgedComparison j;
    j.measured = ojson{{"generator", gen}, {"steps", steps}};
    j.verdict.rule = "every step's flicker interval below 1 and error interval above 1";
    j.verdict.outcome = all_hold ? Outcome::kHolds : any_fails ? Outcome::kDoesNotHold : Outcome::kInconclusive;
    if (j.verdict.inconclusive())
      j.verdict.reason = unconverged ? kNotConverged + " at some step"
                                     : std::string(kInconclusivePrefix) + ": some step's interval reaches 1";
    claims.push_back(make_claim(
        kFig6Claim, "paper_tables.json claims[4]; DESIGN.md §11a.1",
        "K sweep, " + gen + ": K = " + ks + ": at every step the frame flicker falls and the relative RMSE grows",
        std::move(j)));
  }
}

// A claim the reference decides carries what it was decided on (judge), in each step for Fig. 6.
bool reference_decided(const Claim& c) {
  if (c.measured.contains("reference_metric")) return true;
  if (!c.measured.contains("steps")) return false;
  const ojson& steps = c.measured.at("steps");
  return std::any_of(steps.begin(), steps.end(), [](const ojson& step) {
    return step.contains("error") && step.at("error").contains("reference_metric");
  });
}

// A document before schema 7 was judged by an earlier rule (schema 6: the margin (1 + b) eps_inf;
// schema 5: 10 x the own error); its reference-decided verdicts are kept as it wrote them, not
// judged again (DESIGN.md §11a *Rule*).
void keep_earlier_rule_verdicts(std::vector<Claim>& claims, const QualityModel& m) {
  const bool current = m.schema_version.is_number_integer() && m.schema_version.get<int64_t>() >= 7;
  if (current || !m.claims) return;
  for (Claim& c : claims) {
    if (!reference_decided(c)) continue;
    const auto written = std::find_if(m.claims->begin(), m.claims->end(),
                                      [&](const Claim& w) { return w.criterion == c.criterion && w.text == c.text; });
    if (written != m.claims->end()) c = *written;
  }
}

}  // namespace

void add_claim_verdicts(json& r) {
  const QualityModel m = quality_model_from_json(r, "the quality document");
  std::vector<Claim> claims;
  if (m.frames_static) {
    add_static_claims(claims, m);
    add_animated_claim(claims, m);
    add_k_sweep_claims(claims, m);
    add_occlusion_claims(claims, m);
    keep_earlier_rule_verdicts(claims, m);
  } else {
    claims.push_back(unmeasured_claim(kFig1Claim, "", "every quality claim",
                                      "not measured here (no per-frame series: a quality document before schema 5)"));
  }
  for (const char* t : {"Modified FIS costs about 5 microseconds more in total than Tok15 FIS.",
                        "Modified FIS is about 7-9 times faster than the k-means generators.",
                        "FIS cost is almost independent of the PDF; k-means cost is not.",
                        "Modified FIS needs about five times fewer lines of code than k-means (Table 3)."}) {
    claims.push_back(unmeasured_claim(t, "paper_tables.json claims",
                                      "a timing/code-size claim: see `vsgl-bench tables`", "not measured here"));
  }
  json document = json::array();
  for (const Claim& c : claims) document.push_back(to_json(c, ClaimLayout::kQuality));
  r["claims"] = document;
  r = sorted_keys(r);  // the quality document's keys are sorted, as it was always written
}

}  // namespace vsgl
