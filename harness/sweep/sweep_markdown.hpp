#pragma once
// OUT/sweep.md of `vsgl-bench sweep` (DESIGN.md §10.1), rendered from the sweep document
// (formats/sweep_model.hpp): a table per axis and slice (median and IQR per generator, view and
// phase, the growth and its verdict), the points and cases beyond the device, the PDF frequency at
// each γ and the paper's claims judged on the sweep.
#include <string>

#include "harness/formats/sweep_model.hpp"

namespace vsgl {

std::string sweep_markdown(const SweepModel& sweep);

}  // namespace vsgl
