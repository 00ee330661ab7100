#pragma once
// The two-sided Mann-Whitney U test (Wilcoxon rank-sum): do two sets of timing samples come from
// the same distribution? Used by `vsgl-bench compare` (nvbench-style noise-aware comparison).
// Exact p-value from the U distribution for small samples without ties; otherwise the normal
// approximation with tie correction and continuity correction.
#include <cstddef>
#include <vector>

namespace vsgl {

struct MannWhitneyResult {
  double u1 = 0;        // U of the first sample: pairs (a, b) with a > b, ties counting 1/2
  double u2 = 0;        // n1 n2 - u1
  double p_value = 1;   // two-sided
  bool exact = false;   // from the exact distribution (else normal approximation)
};

// Throws std::invalid_argument when either sample is empty or holds a non-finite value.
MannWhitneyResult mann_whitney_u(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace vsgl
