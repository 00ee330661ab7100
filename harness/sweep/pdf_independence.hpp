#pragma once
// The paper's claim that FIS cost is almost independent of the PDF while k-means cost is not,
// judged on the pdf-sharpness axis (DESIGN.md §10.1): one capture, its PDFs raised to γ, so
// nothing but the PDF changes. Per generator and view the change of the median total at each γ
// from the reference γ (1, the capture's own PDF), and the largest such change, the spread, each
// with a percentile bootstrap interval over the rounds (core/bootstrap.hpp).
//
// Holds when every FIS total's interval stays within ±kFisPdfChangeMax at every γ and each paper
// k-means generator's spread interval lies above every FIS generator's on the same view. Does not
// hold when a FIS total's interval lies wholly outside that band at some γ, or a paper k-means
// spread lies wholly below a FIS one. Inconclusive otherwise.
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
};

struct PdfSpread {
  std::string generator, view;
  bool fis = false;
  bool in_paper = false;
  std::vector<GammaChange> changes;  // by γ, the reference included (change 0)
  double spread = 0;                 // max |change| over γ
  double low = 0, high = 0;
};

struct PdfIndependence {
  std::vector<std::pair<std::string, std::string>> slice;  // the other axes' values
  double reference_gamma = 1;
  double band = 0;  // kFisPdfChangeMax
  double confidence = 0;
  std::size_t resamples = 0;
  std::vector<PdfSpread> spreads;  // per case, in the points' case order
  std::optional<bool> holds;
  std::string note;  // why it does not hold or is inconclusive, or what is missing
};

struct PdfIndependenceOptions {
  std::size_t resamples = 2000;
  double confidence = 0.95;
  std::uint64_t seed = 0x70646669ULL;  // same input and seed -> the same intervals everywhere
};

// One judgement per slice of the pdf-sharpness axis, read off the fits of the totals on it
// (sweep_fits: their slices and points); none when the sweep has no such axis. Throws InputError
// for a slice with fewer than 2 values of γ or a point with fewer than 2 rounds.
std::vector<PdfIndependence> judge_pdf_independence(const MeasuredSweep& sweep, const std::vector<SweepFit>& fits,
                                                    const PdfIndependenceOptions& options = {});

// The sweep document's claim ("id": "pdf_independence"); `text` is the paper's claim.
SweepClaim pdf_independence_claim(const PdfIndependence& judgement, const std::string& text, bool informative);

// "holds", "does not hold", "inconclusive".
std::string verdict_word(const std::optional<bool>& holds);

}  // namespace vsgl
