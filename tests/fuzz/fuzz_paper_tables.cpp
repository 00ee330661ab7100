// libFuzzer target: the paper-tables loader (harness/paper_tables.cpp load_paper_tables, the
// file behind `tables --paper` and `dashboard --paper`), and the dashboard page drawn from a
// paper document that loaded, beside a committed run. Bad input must end in InputError;
// anything else is a bug.
#include <cstdint>
#include <string_view>

#include "fuzz_input_files.hpp"
#include "harness/dashboard_page.hpp"
#include "harness/error.hpp"
#include "harness/paper_tables.hpp"
#include "harness/regression_run.hpp"

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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto file = scratch().write("paper_tables.json", input);
  try {
    const nlohmann::json paper = vsgl::load_paper_tables(file);
    (void)vsgl::dashboard_html({committed_run()}, paper, "fuzz");
  } catch (const vsgl::InputError&) {
  }
  return 0;
}
