#pragma once
// Step 2 of `tables`, once per table input: provide its capture (record a paper table's when
// missing; a --capture must exist), upload both
// views, build and record every generator on each (DESIGN.md §9: inputs uploaded and command buffers
// recorded before any timing), and time them interleaved with the protocol of timing_runner.hpp.
#include <functional>

#include <nlohmann/json.hpp>

#include "harness/report/measured_table.hpp"
#include "harness/report/tables_run.hpp"

namespace vsgl {

class Device;

struct TableMeasurement {
  MeasuredTable table;
  nlohmann::ordered_json config;  // config_json() of its capture
};

// A case (generator on a view) whose buffers the device cannot hold (a DeviceLimitError while it
// was built), left out of the timing.
struct CaseBeyondDevice {
  std::string generator, view, reason;
};

// The timing step alone, on a capture in memory (`sweep` times captures it altered): both views
// uploaded, every generator of `options` built and recorded on each at its view's N, then timed
// interleaved (timing_runner.hpp). Throws what upload_view, make_generator and TimingRunner throw;
// with `beyond`, a case the device cannot hold is listed there and the others are timed (a
// DeviceLimitError still ends the call when no case is left).
TimingResult time_capture(Device& device, const TablesOptions& options, const Capture& capture,
                          const std::function<void(const TimingProgress&)>& progress = {},
                          std::vector<CaseBeyondDevice>* beyond = nullptr);

TableMeasurement measure_table(Device& device, const TablesOptions& options, const TableInput& input,
                               const std::function<void(const TablesEvent&)>& on_event);

}  // namespace vsgl
