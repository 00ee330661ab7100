// `vsgl-bench dashboard RESULTS_DIR --out SITE` (DESIGN.md §10): SITE/index.html, one self-contained
// page (inline SVG charts, no script, nothing fetched) from every table JSON under RESULTS_DIR,
// beside the paper's numbers (harness/compare/dashboard_page.hpp).
#include <cstdio>
#include <filesystem>

#include "bench/cli/commands.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/compare/dashboard_page.hpp"
#include "harness/core/error.hpp"
#include "bench/cli/dashboard_generators.hpp"
#include "harness/report/paper_tables.hpp"

namespace vsgl::cli {

int run_dashboard(std::vector<std::string> tokens) {
  const std::vector<std::string> dirs = take_positionals(tokens, {"--out", "--paper"});
  Args args(tokens);
  const auto out = args.value("--out");
  const std::filesystem::path paper_path =
      args.string("--paper", (std::filesystem::path(VSGL_SOURCE_DIR) / "results/paper/paper_tables.json").string());
  args.finish();
  if (dirs.size() != 1) throw UsageError("dashboard takes one RESULTS_DIR");
  if (!out) throw UsageError("dashboard needs --out DIR");
  const std::vector<BenchRun> runs = find_table_runs(dirs[0]);
  const nlohmann::json paper = load_paper_tables(paper_path);
  std::filesystem::create_directories(*out);
  const std::filesystem::path page = std::filesystem::path(*out) / "index.html";
  write_text_atomic(page, dashboard_html(runs, paper, dirs[0], dashboard_generators()));
  std::fprintf(stderr, "wrote %s (%zu table runs)\n", page.string().c_str(), runs.size());
  return 0;
}

}  // namespace vsgl::cli
