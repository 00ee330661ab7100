#pragma once
// The paper's six claims (results/paper/paper_tables.json "claims"), each checked on a measured
// table with its threshold named once below; on a CPU device the timing verdicts are informative.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/claim.hpp"
#include "harness/report/measured_table.hpp"

namespace vsgl {

// Claim 3 (the paper's "FIS cost is almost independent of the PDF"): how far a FIS total may move
// when only the PDF changes, between the two tables' scenes here and along the sweep's
// pdf-sharpness axis (sweep/pdf_independence.hpp).
inline constexpr double kFisPdfChangeMax = 0.10;

// Claim 1's rule on an interval [low, high] of the overhead and the bound +-bound_us, the
// interval rule "within (-bound, bound)" of core/claim_verdict.hpp: inside -> holds, wholly
// outside -> does not hold, touching or straddling an end, or short of its confidence ->
// inconclusive (reason kInconclusiveNote, or kInconclusivePrefix and why). Throws
// std::invalid_argument for low > high or a bound that is not positive.
ClaimVerdict judge_overhead(double low_us, double high_us, double bound_us, bool reaches_nominal);

// `other` is the other paper table of the same run (claim 3 compares them), or nullptr. An
// inconclusive verdict's reason is kInconclusiveNote or starts with kInconclusivePrefix
// (formats/claim.hpp).
std::vector<Claim> table_claims(const MeasuredTable& t, const MeasuredTable* other, const ReportContext& ctx);
// The same as the table JSON's "claims" array.
nlohmann::ordered_json claims_json(const MeasuredTable& t, const MeasuredTable* other, const ReportContext& ctx);

}  // namespace vsgl
