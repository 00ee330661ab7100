// vsgl-bench: reproduce the timing tables of Tokuyoshi 2016 (Modified FIS for VSGLs) on any
// Vulkan device. Its command line is bench/cli/vsgl_bench_command_line.hpp; this file names the
// program and maps errors to exit codes (bench/cli/program_main.hpp).
#include "bench/cli/program_main.hpp"
#include "bench/cli/vsgl_bench_command_line.hpp"

int main(int argc, char** argv) {
  return vsgl::cli::run_program("vsgl-bench", argc, argv,
                                [](int n, char** args) { return vsgl::cli::vsgl_bench_command_line(n, args); });
}
