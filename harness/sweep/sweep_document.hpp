#pragma once
// The sweep document (formats/sweep_model.hpp, DESIGN.md §10.1) filled from a measured sweep: every
// point's parameters, statistics and raw samples, every fit with its expectation and verdict, and
// the paper's claims judged on it. OUT/sweep.json, sweep.md and the plots are all rendered from it
// (to_json, sweep_markdown.hpp, sweep_plots.hpp).
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/sweep_model.hpp"
#include "harness/sweep/measured_sweep.hpp"
#include "harness/sweep/pdf_independence.hpp"

namespace vsgl {

// Everything of the run that is not a measurement.
struct SweepContext {
  DeviceRecord device;            // device_record(DeviceInfo)
  BuildRecord build;              // this_build()
  RunRecord run;                  // started, validation, quick, clocks (run_record)
  nlohmann::ordered_json paper;   // results/paper/paper_tables.json (its claim texts); null: none
  bool informative = false;       // a CPU device: its timing verdicts say nothing of a GPU
};

// `claims`: the PDF-independence judgements (pdf_independence.hpp); none: the document has no
// "claims" (a sweep without a pdf-sharpness axis, or one still running).
SweepModel sweep_document(const MeasuredSweep& sweep, const std::vector<SweepFit>& fits, const SweepContext& context,
                          const std::vector<PdfIndependence>& claims = {});

}  // namespace vsgl
