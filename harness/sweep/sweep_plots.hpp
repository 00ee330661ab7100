#pragma once
// The SVG plots of `vsgl-bench sweep` (DESIGN.md §10.1), rendered from the sweep document
// (formats/sweep_model.hpp): one log-log plot per axis and phase, per series (generator, view and
// slice) the medians over the q1-q3 band.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "harness/formats/sweep_model.hpp"
#include "harness/sweep/sweep_axis.hpp"

namespace vsgl {

// File name and contents of each plot: "sweep_<axis>_<phase>.svg". An axis/phase with no point on a
// log axis has no plot. With the paper's tables and `paper_table`, the paper table whose input the
// scene is (report/tables_run.hpp paper_table_of; 0: none), a series at the paper's setup
// (paper_reference_x) marks the paper's time there.
std::vector<std::pair<std::string, std::string>> sweep_plots(const SweepModel& sweep,
                                                             const nlohmann::ordered_json* paper = nullptr,
                                                             int paper_table = 0);

// Where the paper's setup ("setup" of paper_tables.json: N 2048 on the camera view and 1024 on the
// light view, a 1920x1088 G-buffer, a 512 RSM, K 1; and γ 1, its own PDF) sits on an axis for a
// view, in growth_x units; none where the axis does not touch the view or the paper gives no value
// (k-means iterations).
std::optional<double> paper_reference_x(const nlohmann::ordered_json& paper, SweepParameter parameter,
                                        const std::string& view);

}  // namespace vsgl
