#pragma once
// Step 2 of `tables`, once per table input: provide its capture (record a paper table's when
// missing; a --capture must exist), upload both
// views, build and record every generator on each (DESIGN.md §9: inputs uploaded and command buffers
// recorded before any timing), and time them interleaved with the protocol of timing_runner.hpp.
#include <functional>

#include <nlohmann/json.hpp>

#include "harness/report/capture_cases.hpp"
#include "harness/report/measured_table.hpp"
#include "harness/report/tables_run.hpp"
#include "harness/scene/capture_provisioning.hpp"

namespace vsgl {

class Device;

struct TableMeasurement {
  MeasuredTable table;
  nlohmann::ordered_json config;  // config_json() of its capture
};

// The capture of a table input: a paper table's recorded when missing or stale
// (provide_table_capture), another loaded with every hash checked. `say` gets the log lines.
ProvidedCapture provide_input_capture(Device& device, const TablesOptions& options, const TableInput& input,
                                      const std::function<void(const std::string&)>& say);

// The timing step alone, on a capture in memory (`sweep` times captures it altered): its cases
// (capture_cases.hpp, where `beyond` is explained) timed interleaved (timing_runner.hpp).
TimingResult time_capture(Device& device, const TablesOptions& options, const Capture& capture,
                          const std::function<void(const TimingProgress&)>& progress = {},
                          std::vector<CaseBeyondDevice>* beyond = nullptr);

TableMeasurement measure_table(Device& device, const TablesOptions& options, const TableInput& input,
                               const std::function<void(const TablesEvent&)>& on_event);

}  // namespace vsgl
