// vsgl-bench-test-build: vsgl-bench with the hooks of the tests that must stop or slow a real run
// (docs/testing.md, "Test hooks"), built beside the tests and never installed or packaged:
//  - VSGL_TEST_PAUSE_AT stops a run at a point of the atomic writer (pause_at_write.hpp);
//  - `tables --debug-slow GENERATOR,...` slows generators (debug_slowdown.hpp), recorded in the
//    run as altered_generators.
// Everything else is the shipped program's command line (bench/cli/vsgl_bench_command_line.hpp).
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/cli/option_types.hpp"
#include "bench/cli/program_main.hpp"
#include "bench/cli/vsgl_bench_command_line.hpp"
#include "debug_slowdown.hpp"
#include "pause_at_write.hpp"
#include "test_kernels.hpp"

int main(int argc, char** argv) {
  vsgl::test::install_pause_at_write_from_environment();
  vsgl::test::add_test_kernels();  // the --debug-slow workload is kernels/test_workload.comp
  auto slowed = std::make_shared<std::vector<std::string>>();
  vsgl::cli::TablesExtension debug_slow;
  debug_slow.add_options = [slowed](CLI::App& tables) {
    vsgl::cli::add_list_option(tables, "--debug-slow", *slowed,
                               "TEST BUILD ONLY: extra work in these generators' last phase (to test `compare`; "
                               "recorded in the JSON as run.altered_generators)",
                               CLI::Validator([](std::string&) { return std::string(); }, "NAME"));
  };
  debug_slow.apply = [slowed](vsgl::TablesOptions& options) {
    if (slowed->empty()) return;
    options.altered_generators = *slowed;
    options.wrap_generator = vsgl::debug_slowdown_of(*slowed);
  };
  return vsgl::cli::run_program("vsgl-bench", argc, argv, [&](int n, char** args) {
    return vsgl::cli::vsgl_bench_command_line(n, args, debug_slow);
  });
}
