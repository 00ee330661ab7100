#pragma once
// `vsgl-bench dashboard RESULTS_DIR --out SITE` (DESIGN.md §10): one self-contained HTML page (inline
// CSS and SVG, no script, nothing fetched) from every table JSON under RESULTS_DIR:
//  - per paper table, a stacked bar chart of the phases (camera view, then light view) per
//    generator for each run, beside the same chart of the paper's GTX 970 numbers
//    (results/paper/paper_tables.json); each chart has its own scale, as devices differ by
//    orders of magnitude; after them, per scene of a capture that is no paper table's
//    (`tables --capture DIR`: "table": null), the same charts without the paper's;
//  - per table (or scene) and generator, the total across runs in time order (date, then commit),
//    one line per device, median with a q1..q3 whisker, on a log axis;
//  - the scaling section: every sweep JSON under RESULTS_DIR, a log-log chart of the totals and a
//    table of the growth fits per axis (dashboard_scaling.hpp);
//  - the frame section: every frame JSON under RESULTS_DIR (`vsgl-bench frame`, DESIGN.md §9.2), a
//    stacked bar per generator of the frame's five phases, one chart per run;
//  - the list of runs (file, device, date, commit, flags).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "harness/compare/dashboard_scaling.hpp"
#include "harness/compare/regression_run.hpp"
#include "harness/formats/frame_model.hpp"

namespace vsgl {

// Every table JSON under `results_dir` (recursively), known by its content (is_table_document),
// whatever its name: the paper's tables (tableN.json) and a capture's (OUT/<scene>.json, read as
// table 0, regression_run.hpp CaptureTables::kRead). Other files, JSON or not (sweep.json, quality
// JSON, schemas), are skipped. Sorted by table (the paper's first, then the others by scene), date,
// commit, path; none is an empty list (a results directory may hold sweeps alone). Throws
// InputError for a table JSON that cannot be read, and for a tableN.json that is not JSON.
std::vector<BenchRun> find_table_runs(const std::filesystem::path& results_dir);

// One frame document (`vsgl-bench frame`) and where it was found.
struct FrameRun {
  std::string path;  // as found under the results directory
  FrameModel model;
};

// Every frame JSON under `results_dir` (recursively), known by its content ("kind": "frame"),
// sorted by path. Other files are skipped. Throws InputError for a frame JSON the model refuses.
std::vector<FrameRun> find_frame_runs(const std::filesystem::path& results_dir);

// What the page shows of a generator, from the descriptor table (generators/generator_registry.hpp;
// dashboard_generators() in bench/cli builds it): the bar label, whether the paper timed it, and its
// phases in order for the paper's bars. A run's generator missing here is labelled by its name.
struct DashboardGenerator {
  std::string name;
  std::string short_label;
  bool in_paper = false;
  std::vector<std::string> phases;
};

// The page. `paper` is results/paper/paper_tables.json (report/paper_tables.hpp load_paper_tables);
// `source` names where the runs came from (shown on the page); `sweeps` (find_sweep_runs) fill the
// scaling section, which with none says so.
std::string dashboard_html(const std::vector<BenchRun>& runs, const nlohmann::ordered_json& paper,
                           const std::string& source, const std::vector<DashboardGenerator>& generators,
                           const std::vector<SweepRun>& sweeps = {}, const std::vector<FrameRun>& frames = {});

}  // namespace vsgl
