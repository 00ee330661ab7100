#pragma once
// The two one-sided tests (TOST, Schuirmann 1987) of whether an estimate lies within an
// equivalence band (-delta, delta), read off the estimate's bootstrap replicates
// (core/bootstrap.hpp): the percentile bootstrap's p-value of a one-sided hypothesis is the share
// of replicates on its null side, counted as (k + 1) / (B + 1) so that no p-value is 0. At level
// alpha, "equivalent" (p_equivalent <= alpha) is the same statement as the (1 - 2 alpha)
// percentile interval lying inside the band.
#include <span>

namespace vsgl {

struct EquivalencePValues {
  // H0: the estimate is at or beyond an end of the band; rejected by both one-sided tests:
  // max(P*(x >= delta), P*(x <= -delta)).
  double equivalent = 1;
  // H0: the estimate lies within [-delta, delta]; against "beyond delta" P*(x <= delta) and
  // against "below -delta" P*(x >= -delta): twice the smaller (both directions are looked at).
  double outside = 1;
};

// Throws std::invalid_argument for no replicates, a replicate that is not finite, or delta not
// positive.
EquivalencePValues bootstrap_equivalence(std::span<const double> replicates, double delta);

}  // namespace vsgl
