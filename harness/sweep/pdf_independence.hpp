#pragma once
// The paper's claim that FIS cost is almost independent of the PDF while k-means cost is not,
// judged on the pdf-sharpness axis (DESIGN.md §10.1): one capture, its PDFs raised to γ, so
// nothing but the PDF changes. Per generator and view the change of the median total at each γ
// from the reference γ (1, the capture's own PDF), and the largest such change, the spread, each
// with a percentile bootstrap interval over the rounds (core/bootstrap.hpp).
//
// The FIS side is an equivalence test (DESIGN.md §10.1): per FIS case (generator, view) the TOST
// at ±kFisPdfChangeMax of its change at every γ (core/equivalence_tost.hpp); the case is
// equivalent when every γ is (an intersection-union test: its p-value is the largest over γ), not
// equivalent when some γ lies outside the band (its p-value the smallest over γ times their
// number), each family Holm-corrected across the FIS cases at alpha (core/holm_correction.hpp).
// Holds when every FIS case is equivalent and each paper k-means generator's spread interval lies
// above every FIS generator's on the same view. Does not hold when a FIS case is not equivalent,
// or a paper k-means spread lies wholly below a FIS one. Inconclusive otherwise.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "harness/formats/sweep_model.hpp"
#include "harness/sweep/measured_sweep.hpp"

namespace vsgl {

struct GammaChange {
  double gamma = 0;
  std::size_t point = 0;  // index into MeasuredSweep::points
  double change = 0;      // median total(γ) / median total(reference γ) - 1
  double low = 0, high = 0;
  bool reference = false;                  // the reference γ itself: change 0 by construction, not tested
  double p_equivalent = 1, p_outside = 1;  // TOST at ±band (core/equivalence_tost.hpp); 1 at the reference
};

struct PdfSpread {
  std::string generator, view;
  bool fis = false;
  bool in_paper = false;
  std::vector<GammaChange> changes;  // by γ, the reference included (change 0)
  double spread = 0;                 // max |change| over γ
  double low = 0, high = 0;
  // FIS cases: p_equivalent the largest over γ (every γ must be within the band), p_outside the
  // smallest over γ times the number of γ (some γ outside), at most 1; the levels Holm's
  // alpha / (m - rank + 1) in each family.
  std::optional<SweepClaimEquivalence> equivalence;
};

struct PdfIndependence {
  std::vector<std::pair<std::string, std::string>> slice;  // the other axes' values
  double reference_gamma = 1;
  double band = 0;  // kFisPdfChangeMax
  double confidence = 0;
  double alpha = 0;  // the family-wise level of the equivalence tests
  std::size_t resamples = 0;
  std::vector<PdfSpread> spreads;  // per case, in the points' case order
  // None: the slice lacks a FIS or a paper k-means generator, `note` says so. The reason says why
  // it does not hold or is inconclusive.
  std::optional<ClaimVerdict> verdict;
  std::string note;
};

struct PdfIndependenceOptions {
  std::size_t resamples = 2000;
  double confidence = 0.95;            // of the intervals shown
  double alpha = 0.05;                 // of the equivalence tests, across the FIS cases (Holm)
  std::uint64_t seed = 0x70646669ULL;  // same input and seed -> the same intervals everywhere
};

// One judgement per slice of the pdf-sharpness axis, read off the fits of the totals on it
// (sweep_fits: their slices and points); none when the sweep has no such axis. Throws InputError
// for a slice with fewer than 2 values of γ or a point with fewer than 2 rounds.
std::vector<PdfIndependence> judge_pdf_independence(const MeasuredSweep& sweep, const std::vector<SweepFit>& fits,
                                                    const PdfIndependenceOptions& options = {});

// The sweep document's claim ("id": "pdf_independence"); `text` is the paper's claim.
SweepClaim pdf_independence_claim(const PdfIndependence& judgement, const std::string& text, bool informative);

// Each FIS case's verdict from its two p-values, Holm-corrected across the cases at `alpha`; the
// other spreads are left alone. (Exposed so a test can give it p-values directly.)
void judge_fis_equivalence(std::vector<PdfSpread>& spreads, double alpha);

}  // namespace vsgl
