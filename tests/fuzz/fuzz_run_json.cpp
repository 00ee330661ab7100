// libFuzzer target: the run/table JSON loader behind `compare`, `export` and `dashboard`
// (harness/compare/regression_run.cpp load_bench_run: a table JSON or vsgl-gbench JSON), and what those
// commands then do with a run that loaded: both export formats, a comparison of the run with
// itself and its markdown report, and (table JSON) the dashboard page. Then the dashboard's own
// reading of a folder holding the input under a paper table's name and a user scene's
// (find_table_runs: table documents known by content, a capture's "table": null read as its
// scene's section) and the page drawn from what it found. Bad input must end in InputError;
// anything else is a bug.
#include <cstdint>
#include <string_view>

#include "fuzz_input_files.hpp"
#include "harness/compare/dashboard_page.hpp"
#include "harness/core/error.hpp"
#include "harness/compare/export_formats.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/compare/regression_compare.hpp"
#include "harness/compare/regression_run.hpp"

namespace {

const vsgl::fuzz::ScratchDir& scratch() {
  static const vsgl::fuzz::ScratchDir dir;
  return dir;
}

const nlohmann::ordered_json& paper() {
  static const nlohmann::ordered_json doc =
      vsgl::load_paper_tables(std::filesystem::path(VSGL_SOURCE_DIR) / "results/paper/paper_tables.json");
  return doc;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto file = scratch().write("table1.json", input);
  try {
    const vsgl::BenchRun run = vsgl::load_bench_run(file);
    for (auto format : {vsgl::ExportFormat::kGithubActionBenchmark, vsgl::ExportFormat::kBencherMetricFormat})
      (void)vsgl::export_run(run, format).dump();
    vsgl::CompareOptions options;
    const vsgl::RunComparison c = vsgl::compare_runs(run, run, options);
    (void)vsgl::comparison_markdown(run, run, c, options);
    if (run.format == "table") (void)vsgl::dashboard_html({run}, paper(), "fuzz", {});  // it reads table JSON only
  } catch (const vsgl::InputError&) {
  }
  scratch().write("my_scene.json", input);
  try {
    (void)vsgl::dashboard_html(vsgl::find_table_runs(file.parent_path()), paper(), "fuzz", {});
  } catch (const vsgl::InputError&) {}
  return 0;
}
