// libFuzzer target: the paper-tables loader (harness/report/paper_tables.cpp load_paper_tables, the
// file behind `tables --paper` and `dashboard --paper`), and the dashboard page drawn from a
// paper document that loaded, beside a committed run. Bad input must end in InputError;
// anything else is a bug.
#include <cstdint>
#include <string_view>

#include "fuzz_input_files.hpp"
#include "harness/compare/dashboard_page.hpp"
#include "harness/core/error.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/compare/regression_run.hpp"

namespace {

const vsgl::fuzz::ScratchDir& scratch() {
  static const vsgl::fuzz::ScratchDir dir;
  return dir;
}

const vsgl::BenchRun& committed_run() {
  static const vsgl::BenchRun run =
      vsgl::load_bench_run_path(std::filesystem::path(VSGL_SOURCE_DIR) / "results/lavapipe");
  return run;
}

// The page's generators as the loaded file names them (so the fuzzed names and phases reach the
// paper's bars): each generator of Table 1 with the phases of its camera view.
std::vector<vsgl::DashboardGenerator> generators_of(const nlohmann::ordered_json& paper) {
  std::vector<vsgl::DashboardGenerator> out;
  for (const auto& [name, entry] : paper["tables"]["1"].items()) {
    vsgl::DashboardGenerator g{name, name, true, {}};
    for (const auto& [phase, ms] : entry["camera_view"].items()) g.phases.push_back(phase);
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto file = scratch().write("paper_tables.json", input);
  try {
    const nlohmann::ordered_json paper = vsgl::load_paper_tables(file);
    (void)vsgl::dashboard_html({committed_run()}, paper, "fuzz", generators_of(paper));
  } catch (const vsgl::InputError&) {
  }
  return 0;
}
