#pragma once
// Step 1 of `tables`: everything a table reports that is not a measurement — device, build,
// run flags, the paper's numbers, the schema, Table 3's counted lines and shaders — gathered
// before any timing, so that a bad paper file or schema fails in seconds, not after the run.
#include <nlohmann/json.hpp>

#include "harness/report/measured_table.hpp"
#include "harness/report/tables_run.hpp"

namespace vsgl {

struct RunContext {
  ReportContext report;
  nlohmann::ordered_json schema;  // results/schema/table.schema.json
};

// Throws InputError for an unreadable paper file, schema or generator source.
RunContext make_run_context(const DeviceInfo& device, const TablesOptions& options);

// The "run" block: when it started (UTC), the validation layer, --quick, whether the protocol is
// DESIGN.md §9's, the clocks claim, and TEST-ONLY slowed generators. `sweep` writes the same.
RunRecord run_record(const TablesOptions& options);

// The table JSON's "config" block for one capture.
nlohmann::ordered_json config_json(const TablesOptions& options, const Capture& capture, const DeviceInfo& device);

}  // namespace vsgl
