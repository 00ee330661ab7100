// `vsgl-bench dashboard RESULTS_DIR --out SITE` (DESIGN.md §10): SITE/index.html, one self-contained
// page (inline SVG charts, no script, nothing fetched) from every table JSON under RESULTS_DIR,
// a paper table's beside the paper's numbers, and every sweep JSON's scaling (harness/compare/dashboard_page.hpp,
// dashboard_scaling.hpp).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/cli/commands.hpp"
#include "bench/cli/option_types.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/compare/dashboard_page.hpp"
#include "harness/compare/dashboard_scaling.hpp"
#include "harness/core/error.hpp"
#include "bench/cli/dashboard_generators.hpp"
#include "harness/report/paper_tables.hpp"

namespace vsgl::cli {

Command add_dashboard_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "dashboard",
      "OUT/index.html: one self-contained page of inline SVG charts (no script, nothing fetched) of every table "
      "JSON under RESULTS_DIR, known by its content (the paper's tableN.json and a capture's OUT/<scene>.json of "
      "`tables --capture`): phases per generator per run, beside the paper for a paper table, totals across "
      "runs; and of every sweep JSON (sweep.json of `sweep`): per axis the totals on a log-log chart and the "
      "growth fits with their verdicts");
  struct Options {
    std::string results;
    std::string out;
    std::optional<std::string> paper;  // none: the copy built in
  };
  auto o = std::make_shared<Options>();
  app->add_option("RESULTS_DIR", o->results,
                  "directory searched for table JSON (any *.json that is one), sweep JSON (sweep.json) and frame JSON "
                  "(frame.json)")
      ->required();
  app->add_option("--out", o->out, "output directory")->required()->type_name("DIR");
  add_optional(*app, "--paper", o->paper, "the paper's tables (default: the copy built into vsgl-bench)")
      ->check(input_file("--paper"))
      ->default_str("built-in results/paper/paper_tables.json");
  return {app, [o] {
            const std::vector<BenchRun> runs = find_table_runs(path_from_utf8(o->results));
            const std::vector<SweepRun> sweeps = find_sweep_runs(path_from_utf8(o->results));
            const std::vector<FrameRun> frames = find_frame_runs(path_from_utf8(o->results));
            if (runs.empty() && sweeps.empty() && frames.empty())
              throw InputError(o->results +
                               ": no table JSON (the output of `tables`), no sweep JSON (sweep.json) and no frame JSON "
                               "(frame.json) found");
            const nlohmann::ordered_json paper = paper_tables_or_built_in(
                o->paper ? std::optional<std::filesystem::path>(path_from_utf8(*o->paper)) : std::nullopt);
            std::filesystem::create_directories(path_from_utf8(o->out));
            const std::filesystem::path page = path_from_utf8(o->out) / "index.html";
            write_text_atomic(page, dashboard_html(runs, paper, o->results, dashboard_generators(), sweeps, frames));
            std::fprintf(stderr, "wrote %s (%zu table runs, %zu sweep files, %zu frame files)\n",
                         path_text(page).c_str(), runs.size(), sweeps.size(), frames.size());
            return 0;
          }};
}

}  // namespace vsgl::cli
