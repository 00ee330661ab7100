#pragma once
// The paper's six claims (results/paper/paper_tables.json "claims"), each checked on a measured
// table with its threshold named once below; on a CPU device the timing verdicts are informative.
#include <nlohmann/json.hpp>

#include "harness/report/measured_table.hpp"

namespace vsgl {

// `other` is the other paper table of the same run (claim 3 compares them), or nullptr.
nlohmann::ordered_json claims_json(const MeasuredTable& t, const MeasuredTable* other, const ReportContext& ctx);

}  // namespace vsgl
