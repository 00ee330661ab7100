#pragma once
// The dashboard's scaling section (DESIGN.md §10, §10.1): every sweep JSON under RESULTS_DIR
// (`sweep.json`, written by `vsgl-bench sweep`), one block per file, labelled by device, scene,
// commit, date and path (and, for one written while its run went on, "incomplete: N of M
// points"), and per axis:
//  - a log-log chart of each generator's total per view (and slice of the other axes): median
//    over the q1..q3 band; points whose growth x is 0 (γ = 0) are left off the log axis;
//  - a table of those totals at every value of the axis, γ = 0 included;
//  - a table of the fits of the totals and phases: growth with its interval, the expectation and
//    the verdict, a fit whose interval excludes the expectation highlighted;
// and the paper's claims judged on the sweep, when the file has them. All text escaped; no
// script, nothing fetched.
#include <filesystem>
#include <string>
#include <vector>

#include "harness/formats/sweep_model.hpp"

namespace vsgl {

struct SweepRun {
  std::string path;  // relative to RESULTS_DIR
  SweepModel model;
};

// Every file named sweep.json under `results_dir` (recursively), sorted by scene, date, path.
// None is an empty list. Throws InputError naming the file for one that cannot be read as a sweep.
std::vector<SweepRun> find_sweep_runs(const std::filesystem::path& results_dir);

// The <section id="scaling">; with no sweep, one line that says so (`source` names RESULTS_DIR).
std::string scaling_section_html(const std::vector<SweepRun>& sweeps, const std::string& source);

}  // namespace vsgl
