#pragma once
// Holm's step-down correction for a family of m tests (Holm 1979, "A simple sequentially rejective
// multiple test procedure"): with the p-values sorted ascending, p_(1) <= ... <= p_(m), reject
// H_(1), H_(2), ... while p_(i) <= alpha / (m - i + 1), and stop at the first that is not. The
// chance of rejecting any true hypothesis stays at most alpha, however the tests depend on each
// other, and it rejects everything Bonferroni (alpha / m for all) does and more.
#include <cstddef>
#include <span>
#include <vector>

namespace vsgl {

struct HolmDecision {
  std::size_t rank = 0;  // i: 1 for the smallest p-value (ties keep the input order)
  double level = 0;      // alpha / (m - i + 1), the level p_(i) is held to
  bool rejected = false;
};

// One decision per p-value, in the input's order. Throws std::invalid_argument for no p-values, a
// p-value outside [0, 1] or alpha outside (0, 1).
std::vector<HolmDecision> holm_correction(std::span<const double> p_values, double alpha);

}  // namespace vsgl
