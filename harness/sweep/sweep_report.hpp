#pragma once
// The outputs of `vsgl-bench sweep` (DESIGN.md §10.1) from a measured sweep: OUT/sweep.json (schema
// results/schema/sweep.schema.json: every point's parameters, statistics and raw samples, every fit
// with its expectation and verdict), OUT/sweep.md (a table per axis and slice: median and IQR per
// generator, view and phase, and the fits) and one log-log SVG per axis and phase.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/sweep/measured_sweep.hpp"

namespace vsgl {

inline constexpr int kSweepSchemaVersion = 1;

// Everything of the run that is not a measurement.
struct SweepContext {
  nlohmann::ordered_json device;  // to_json(DeviceInfo)
  nlohmann::ordered_json build;   // build_json()
  nlohmann::ordered_json run;     // started, validation, quick, clocks
};

nlohmann::ordered_json sweep_json(const MeasuredSweep& sweep, const std::vector<SweepFit>& fits,
                                  const SweepContext& context);

std::string sweep_markdown(const MeasuredSweep& sweep, const std::vector<SweepFit>& fits);

// File name and contents of each plot: "sweep_<axis>_<phase>.svg", per series (generator, view and
// slice) the medians over the q1-q3 band. An axis/phase with no point on a log axis has no plot.
std::vector<std::pair<std::string, std::string>> sweep_plots(const MeasuredSweep& sweep,
                                                             const std::vector<SweepFit>& fits);

}  // namespace vsgl
