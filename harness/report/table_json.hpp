#pragma once
// The table JSON of DESIGN.md §10 (results/schema/table.schema.json): one file per paper table, with
// per generator, view and phase the statistics of DESIGN.md §9 and the paper's value beside each, the
// ratios the paper argues with, the Table 3 analog, and the paper's claims checked on this run.
#include <string>

#include <nlohmann/json.hpp>

#include "harness/report/measured_table.hpp"

namespace vsgl {

// The table model of a measured table (formats/table_model.hpp), and its document. `other` is the other paper table of the same run (for the Table 1 ->
// Table 2 change), or nullptr. Throws std::invalid_argument when a statistic cannot be computed.
TableModel table_model(const MeasuredTable& table, const MeasuredTable* other, const ReportContext& ctx);
nlohmann::ordered_json table_json(const MeasuredTable& table, const MeasuredTable* other, const ReportContext& ctx);

// The paper's column name of a generator ("[Tok15]", "Ours (modified FIS)", ...).
std::string generator_label(const std::string& generator);

}  // namespace vsgl
