#include "harness/sweep/pdf_independence.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "harness/core/bootstrap.hpp"
#include "harness/core/equivalence_tost.hpp"
#include "harness/core/error.hpp"
#include "harness/core/holm_correction.hpp"
#include "harness/core/text_format.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/table_claims.hpp"

namespace vsgl {
namespace {

std::string percent(double v) { return number_text(100 * v, 3) + "%"; }

std::string interval_text(double v, double low, double high) {
  return percent(v) + " [" + percent(low) + ", " + percent(high) + "]";
}

// The changes and spread of one case along γ, with their bootstrap intervals. Each replicate
// resamples every point's rounds independently (the points are separate runs) and takes the
// reference's median from the same replicate.
PdfSpread spread_of(const MeasuredSweep& s, const SweepFit& f, std::size_t axis, std::size_t ref, double band,
                    const PdfIndependenceOptions& o) {
  PdfSpread out;
  out.generator = f.generator;
  out.view = f.view;
  const GeneratorDescriptor& d = generator_descriptor(f.generator);
  out.fis = d.family == GeneratorFamily::kFis;
  out.in_paper = d.in_paper;
  const std::size_t n = f.points.size();
  std::vector<const std::vector<double>*> samples(n);
  for (std::size_t k = 0; k < n; ++k) {
    samples[k] = &point_samples(s.points[f.points[k]], f.generator, f.view, "total");
    if (samples[k]->size() < 2)
      throw InputError("pdf independence: " + f.generator + " " + f.view + " has " +
                       std::to_string(samples[k]->size()) + " round(s) at point " + std::to_string(f.points[k]) +
                       "; an interval needs at least 2");
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return quantile_sorted(v, 0.5);
  };
  const double ref_median = median(*samples[ref]);
  out.changes.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    GammaChange& c = out.changes[k];
    c.point = f.points[k];
    c.gamma = s.axes[axis].values[s.points[c.point].value_index[axis]].value;
    c.change = median(*samples[k]) / ref_median - 1;
    out.spread = std::max(out.spread, std::abs(c.change));
  }
  BootstrapSampler sampler(o.seed);
  std::vector<std::vector<double>> changes(n, std::vector<double>(o.resamples));
  std::vector<double> spreads(o.resamples), medians(n);
  for (std::size_t b = 0; b < o.resamples; ++b) {
    for (std::size_t k = 0; k < n; ++k) medians[k] = sampler.resampled_median(*samples[k]);
    double spread = 0;
    for (std::size_t k = 0; k < n; ++k) {
      changes[k][b] = medians[k] / medians[ref] - 1;
      spread = std::max(spread, std::abs(changes[k][b]));
    }
    spreads[b] = spread;
  }
  for (std::size_t k = 0; k < n; ++k) {
    out.changes[k].reference = k == ref;
    if (k != ref) {
      const EquivalencePValues p = bootstrap_equivalence(changes[k], band);
      out.changes[k].p_equivalent = p.equivalent;
      out.changes[k].p_outside = p.outside;
    }
    const PercentileInterval i = percentile_interval(changes[k], o.confidence);
    out.changes[k].low = i.low;
    out.changes[k].high = i.high;
  }
  const PercentileInterval i = percentile_interval(spreads, o.confidence);
  out.low = i.low;
  out.high = i.high;
  return out;
}

// The claim's rule on one slice's spreads (the header says it in words).
void judge(PdfIndependence& j) {
  std::vector<std::string> refuted, open;
  bool any_fis = false, any_kmeans = false;
  judge_fis_equivalence(j.spreads, j.alpha);
  for (const PdfSpread& p : j.spreads) {
    if (p.fis) any_fis = true;
    if (!p.fis && p.in_paper) any_kmeans = true;
    if (!p.equivalence) continue;
    const SweepClaimEquivalence& e = *p.equivalence;
    // The γ that decides: the largest TOST p-value (equivalence), the smallest outside one.
    const GammaChange* worst = nullptr;
    for (const GammaChange& c : p.changes) {
      if (c.reference) continue;
      if (e.verdict.fails() ? (!worst || c.p_outside < worst->p_outside)
                            : (!worst || c.p_equivalent > worst->p_equivalent))
        worst = &c;
    }
    const std::string at = worst ? " (at γ=" + number_text(worst->gamma, 4) + " moves " +
                                       interval_text(worst->change, worst->low, worst->high) + ")"
                                 : std::string();
    if (e.verdict.fails())
      refuted.push_back(p.generator + " " + p.view + " is not within ±" + percent(j.band) + at + ": p " +
                        number_text(e.p_outside, 3) + " <= Holm level " + number_text(e.level_outside, 3));
    else if (e.verdict.inconclusive())
      open.push_back(p.generator + " " + p.view + " not shown within ±" + percent(j.band) + at + ": TOST p " +
                     number_text(e.p_equivalent, 3) + ", Holm level " + number_text(e.level_equivalent, 3) +
                     (e.p_equivalent <= e.level_equivalent ? " (Holm stopped at a smaller p-value)" : ""));
  }
  for (const PdfSpread& k : j.spreads) {
    if (k.fis || !k.in_paper) continue;
    for (const PdfSpread& f : j.spreads) {
      if (!f.fis || f.view != k.view) continue;
      const std::string what = k.generator + " spread " + interval_text(k.spread, k.low, k.high) + " vs " +
                               f.generator + " " + interval_text(f.spread, f.low, f.high) + " on " + k.view;
      // The edge convention of core/claim_verdict.hpp: intervals that touch overlap.
      if (k.high < f.low) refuted.push_back(what + ": k-means moves less");
      else if (!(k.low > f.high)) open.push_back(what + ": the intervals overlap");
    }
  }
  // The first few reasons; the JSON's "measured" has every number.
  const auto joined = [](const std::vector<std::string>& v) {
    constexpr std::size_t kShown = 3;
    std::string s;
    for (std::size_t i = 0; i < v.size() && i < kShown; ++i) s += (s.empty() ? "" : "; ") + v[i];
    if (v.size() > kShown) s += "; and " + std::to_string(v.size() - kShown) + " more";
    return s;
  };
  j.verdict.reset();
  j.note.clear();
  if (!any_fis || !any_kmeans) {
    j.note = "needs a FIS generator and a paper k-means generator on the pdf-sharpness axis";
    return;
  }
  ClaimVerdict v;
  v.rule = "every FIS case equivalent (TOST, Holm) and every paper k-means spread interval above every FIS one";
  if (!refuted.empty()) {
    v.outcome = Outcome::kDoesNotHold;
    v.reason = joined(refuted);
  } else if (!open.empty()) {
    v.outcome = Outcome::kInconclusive;
    v.reason = std::string(kInconclusivePrefix) + ": " + joined(open);
  } else {
    v.outcome = Outcome::kHolds;
  }
  j.verdict = std::move(v);
}

}  // namespace

void judge_fis_equivalence(std::vector<PdfSpread>& spreads, double alpha) {
  std::vector<std::size_t> fis;
  std::vector<double> p_equivalent, p_outside;
  for (std::size_t i = 0; i < spreads.size(); ++i) {
    const PdfSpread& p = spreads[i];
    if (!p.fis) continue;
    double largest = 0, smallest = 1;
    std::size_t tested = 0;
    for (const GammaChange& c : p.changes) {
      if (c.reference) continue;
      largest = std::max(largest, c.p_equivalent);
      smallest = std::min(smallest, c.p_outside);
      ++tested;
    }
    if (tested == 0) largest = 1;
    fis.push_back(i);
    p_equivalent.push_back(largest);
    p_outside.push_back(std::min(1.0, smallest * static_cast<double>(std::max<std::size_t>(tested, 1))));
  }
  if (fis.empty()) return;
  const std::vector<HolmDecision> eq = holm_correction(p_equivalent, alpha);
  const std::vector<HolmDecision> out = holm_correction(p_outside, alpha);
  for (std::size_t k = 0; k < fis.size(); ++k) {
    SweepClaimEquivalence e;
    e.p_equivalent = p_equivalent[k];
    e.p_outside = p_outside[k];
    e.level_equivalent = eq[k].level;
    e.level_outside = out[k].level;
    e.verdict.outcome = eq[k].rejected    ? Outcome::kHolds
                        : out[k].rejected ? Outcome::kDoesNotHold
                                          : Outcome::kInconclusive;
    e.verdict.rule = kEquivalenceRule;
    spreads[fis[k]].equivalence = e;
  }
}

std::vector<PdfIndependence> judge_pdf_independence(const MeasuredSweep& s, const std::vector<SweepFit>& fits,
                                                    const PdfIndependenceOptions& o) {
  std::vector<PdfIndependence> out;
  std::optional<std::size_t> axis;
  for (std::size_t a = 0; a < s.axes.size(); ++a)
    if (s.axes[a].parameter == SweepParameter::kPdfSharpness) axis = a;
  if (!axis) return out;
  std::map<std::string, std::size_t> slice_index;
  for (const SweepFit& f : fits) {
    if (f.axis != *axis || f.phase != "total") continue;
    const std::string key = slice_text(f.slice);
    if (!slice_index.contains(key)) {
      slice_index[key] = out.size();
      PdfIndependence j;
      j.slice = f.slice;
      j.band = kFisPdfChangeMax;
      j.confidence = o.confidence;
      j.alpha = o.alpha;
      j.resamples = o.resamples;
      out.push_back(std::move(j));
    }
    PdfIndependence& j = out[slice_index.at(key)];
    if (f.points.size() < 2)
      throw InputError("pdf independence: the pdf-sharpness axis needs at least 2 values of γ" +
                       (key.empty() ? std::string() : " at " + key));
    // The capture's own PDF (γ = 1) when timed, else the first γ.
    std::size_t ref = 0;
    for (std::size_t k = 0; k < f.points.size(); ++k)
      if (s.axes[*axis].values[s.points[f.points[k]].value_index[*axis]].value == 1.0) ref = k;
    j.reference_gamma = s.axes[*axis].values[s.points[f.points[ref]].value_index[*axis]].value;
    j.spreads.push_back(spread_of(s, f, *axis, ref, j.band, o));
  }
  for (PdfIndependence& j : out) judge(j);
  return out;
}

SweepClaim pdf_independence_claim(const PdfIndependence& j, const std::string& text, bool informative) {
  SweepClaim s;
  Claim& c = s.claim;
  c.id = "pdf_independence";
  c.text = text;
  s.axis = sweep_parameter_name(SweepParameter::kPdfSharpness);
  s.slice = j.slice;
  c.criterion = "change of each view's median total from γ=" + number_text(j.reference_gamma, 4) + " (bootstrap " +
                number_text(100 * j.confidence, 3) + "% intervals, " + std::to_string(j.resamples) +
                " resamples): each FIS case (generator, view) equivalent within ±" + percent(j.band) +
                " by TOST at every γ (p = the largest over γ), Holm-corrected across the FIS cases at α=" +
                number_text(j.alpha, 3) +
                ", and each paper k-means generator's spread (max |change| over γ) above every FIS generator's on "
                "the same view; a FIS case outside the band at some γ (p = the smallest over γ times their "
                "number, Holm-corrected) or a k-means spread wholly below a FIS one: does not hold; otherwise "
                "inconclusive";
  s.alpha = j.alpha;
  s.reference_gamma = j.reference_gamma;
  s.band = j.band;
  for (const PdfSpread& p : j.spreads) {
    SweepClaimMeasure m{p.generator, p.view, p.fis ? "fis" : "kmeans", p.in_paper, p.spread, p.low, p.high, {}, {}};
    for (const GammaChange& g : p.changes) {
      SweepClaimChange change{g.gamma, g.point, g.change, g.low, g.high, {}, {}};
      if (p.equivalence && !g.reference) {
        change.p_equivalent = g.p_equivalent;
        change.p_outside = g.p_outside;
      }
      m.changes.push_back(change);
    }
    m.equivalence = p.equivalence;
    s.measures.push_back(std::move(m));
  }
  c.verdict = j.verdict;
  c.note = j.note;
  c.informative = informative;
  return s;
}

}  // namespace vsgl
