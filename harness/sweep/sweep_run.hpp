#pragma once
// `vsgl-bench sweep` as a library function (DESIGN.md §10.1): the tables' protocol (the same
// capture provisioning, uploads, recorded cases and interleaved timing, report/table_timing.hpp)
// at every point of the product of one or more axes, then the growth fits, and OUT/sweep.json
// (validated against results/schema/sweep.schema.json), OUT/sweep.md and the SVG plots, written
// atomically once everything is complete. Before that, OUT/sweep.json is rewritten after each point
// with the points so far and "complete": false, so a run cut short keeps what it measured.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "harness/formats/sweep_model.hpp"
#include "harness/sweep/measured_sweep.hpp"
#include "harness/sweep/pdf_independence.hpp"
#include "harness/sweep/sweep_event.hpp"
#include "harness/sweep/sweep_options.hpp"

namespace vsgl {

class Device;

struct SweepOutcome {
  MeasuredSweep measured;
  std::vector<SweepFit> fits;
  std::vector<PdfIndependence> claims;  // on a pdf-sharpness axis
  SweepModel document;                  // what OUT/sweep.json holds
  std::string markdown;
  std::vector<std::filesystem::path> written;
};

// Throws UsageError for bad options (check_sweep_options, before any work), InputError for a bad
// capture, scene or schema, DeviceError as `tables` and for a sweep with fewer than 2 points the
// device can hold.
SweepOutcome run_sweep(Device& device, const SweepOptions& options,
                       const std::function<void(const SweepEvent&)>& on_event = {});

}  // namespace vsgl
