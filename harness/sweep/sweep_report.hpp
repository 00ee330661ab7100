#pragma once
// The outputs of `vsgl-bench sweep` (DESIGN.md §10.1) from a measured sweep: OUT/sweep.json (schema
// results/schema/sweep.schema.json: every point's parameters, statistics and raw samples, every fit
// with its expectation and verdict), OUT/sweep.md (a table per axis and slice: median and IQR per
// generator, view and phase, and the fits) and one log-log SVG per axis and phase.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/sweep/measured_sweep.hpp"
#include "harness/sweep/pdf_independence.hpp"

namespace vsgl {

inline constexpr int kSweepSchemaVersion = 1;

// Everything of the run that is not a measurement.
struct SweepContext {
  nlohmann::ordered_json device;  // to_json(DeviceInfo)
  nlohmann::ordered_json build;   // build_json()
  nlohmann::ordered_json run;     // started, validation, quick, clocks
  nlohmann::json paper;           // results/paper/paper_tables.json (its claim texts); null: none
  bool informative = false;       // a CPU device: its timing verdicts say nothing of a GPU
};

// `claims`: the PDF-independence judgements (pdf_independence.hpp), the JSON's "claims" array.
nlohmann::ordered_json sweep_json(const MeasuredSweep& sweep, const std::vector<SweepFit>& fits,
                                  const SweepContext& context, const std::vector<PdfIndependence>& claims = {});

std::string sweep_markdown(const MeasuredSweep& sweep, const std::vector<SweepFit>& fits,
                           const std::vector<PdfIndependence>& claims = {});

// File name and contents of each plot: "sweep_<axis>_<phase>.svg", per series (generator, view and
// slice) the medians over the q1-q3 band. An axis/phase with no point on a log axis has no plot.
// With the paper's tables and a scene that is the input of one of them (MeasuredSweep::paper_table),
// a series at the paper's setup (paper_reference_x) marks the paper's time there.
std::vector<std::pair<std::string, std::string>> sweep_plots(const MeasuredSweep& sweep,
                                                             const std::vector<SweepFit>& fits,
                                                             const nlohmann::json* paper = nullptr);

// Where the paper's setup ("setup" of paper_tables.json: N 2048 on the camera view and 1024 on the
// light view, a 1920x1088 G-buffer, a 512 RSM, K 1; and γ 1, its own PDF) sits on an axis for a
// view, in growth_x units; none where the axis does not touch the view or the paper gives no value
// (k-means iterations).
std::optional<double> paper_reference_x(const nlohmann::json& paper, SweepParameter parameter, const std::string& view);

}  // namespace vsgl
