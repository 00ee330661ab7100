#pragma once
// The quality document's claim verdicts (DESIGN.md §11a.1): every claim judged on per-frame series
// paired by frame, with a bootstrap interval against a bound fixed before the run, and the claims
// on an error against the reference also by the reference's ladder in that metric and by the same
// claim against its stride-2 rung (DESIGN.md §11a *Rule*, quality_reference.hpp).
#include <nlohmann/json.hpp>

namespace vsgl {

// Adds "claims" to a quality document written by run_quality, from its model alone (so the
// verdicts can be recomputed from a committed file). A document without per-frame series (schema
// 4 and older) gets its claims as "not measured here". A document without a reference ladder
// (schema 5) keeps the reference-decided verdicts it carries, judged by the rule of its time; where
// it carries none they are "reference not converged (no reference ladder)". Throws InputError for a
// document the model cannot read.
void add_claim_verdicts(nlohmann::ordered_json& result);

}  // namespace vsgl
