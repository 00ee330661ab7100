#pragma once
// `vsgl-bench compare BASE NEW` (DESIGN.md §10): a verdict per benchmark row (every phase, view total
// and generator total both runs have) from the raw samples (regression_verdict.hpp: Mann-Whitney
// U test + minimum relevant change), a geometric-mean summary, and a markdown report.
//
// Comparable runs: the same capture (hashes) and the same workload config per table, the same
// format (table JSON samples are single replays, Google Benchmark samples are repetition means).
// Anything else is refused unless allow_mismatch, and then listed in the report. Different
// devices are allowed and labelled: the verdicts then compare devices, not code.
#include <string>
#include <vector>

#include "harness/compare/regression_run.hpp"
#include "harness/compare/regression_verdict.hpp"

namespace vsgl {

struct CompareOptions {
  VerdictConfig verdict;
  bool allow_mismatch = false;
};

struct RowComparison {
  std::string name;
  bool total = false;     // a view or generator total
  std::size_t base_samples = 0;
  std::size_t new_samples = 0;
  Comparison result;
};

struct RunComparison {
  std::vector<RowComparison> rows;         // in BASE's order
  std::vector<std::string> only_in_base;   // rows without a partner (not compared)
  std::vector<std::string> only_in_new;
  std::vector<std::string> mismatches;     // what made the runs incomparable (allowed)
  bool different_devices = false;
  double geomean_ratio = 1;         // geometric mean of NEW/BASE medians over every row
  double geomean_ratio_totals = 1;  // ... over the generator totals (or view totals without them)

  std::size_t count(Verdict v) const;
};

// Throws InputError when the runs are incomparable (and !allow_mismatch), when they have no row
// in common, or a row's samples cannot be compared (a non-positive median).
RunComparison compare_runs(const BenchRun& base, const BenchRun& fresh, const CompareOptions& options);

// The report: who was compared, the settings, one table row per benchmark with both medians,
// the change in %, p and the verdict, and the summary.
std::string comparison_markdown(const BenchRun& base, const BenchRun& fresh, const RunComparison& comparison,
                                const CompareOptions& options);

// Which verdicts fail a CI gate: "slower", "ambiguous", "faster", comma-separated, or "none".
// Throws UsageError for anything else.
std::vector<Verdict> parse_fail_on(const std::string& list);

}  // namespace vsgl
