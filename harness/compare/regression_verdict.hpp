#pragma once
// Is NEW faster, slower, or the same as BASE? A verdict from raw timing samples that a CI gate
// can act on: a Mann-Whitney U test says whether the difference is real, a minimum relevant
// change says whether it matters.
#include <string>
#include <vector>

namespace vsgl {

enum class Verdict { kFaster, kSlower, kSame, kAmbiguous };
const char* verdict_name(Verdict v);  // "FASTER" | "SLOWER" | "SAME" | "AMBIGUOUS"

struct VerdictConfig {
  double alpha = 0.05;        // significance level of the U test
  double min_change = 0.02;   // relative change of the median below which nothing matters
  // A change is relevant only if it also exceeds noise_factor x the larger relative IQR of the
  // two runs (nvbench-style): run-to-run drift on a noisy device (a CPU driver, a shared runner)
  // moves medians by about one IQR and is not a code change. 0 turns this off.
  double noise_factor = 1.0;
  std::size_t min_samples = 5;
};

struct Comparison {
  double base_median = 0;
  double new_median = 0;
  double change = 0;    // new_median / base_median - 1
  double threshold = 0; // the relevant change for this row: max(min_change, noise_factor x IQR/median)
  double p_value = 1;
  Verdict verdict = Verdict::kAmbiguous;
  std::string reason;   // why, in words
};

// - fewer than min_samples on either side: AMBIGUOUS (cannot decide)
// - |change| < min_change: SAME (whatever the test says, the change is not relevant)
// - |change| < noise_factor x the larger relative IQR: AMBIGUOUS (within the runs' own noise)
// - p < alpha: FASTER or SLOWER by the sign of the change
// - otherwise (the medians moved but the samples overlap too much to tell): AMBIGUOUS
Comparison compare_samples(const std::vector<double>& base, const std::vector<double>& fresh,
                           const VerdictConfig& config = {});

}  // namespace vsgl
