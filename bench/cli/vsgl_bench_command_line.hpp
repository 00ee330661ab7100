#pragma once
// The command line of vsgl-bench: every command declares its own options (CLI11, bench/cli/); the
// whole line is parsed before any command runs (so a typo exits 2 without touching Vulkan), then
// the command given runs and its exit code is returned. The shipped program passes no
// `tables_extension`; the test build of vsgl-bench (tests/hooks/) passes its test-only options.
#include "bench/cli/tables_extension.hpp"

namespace vsgl::cli {

int vsgl_bench_command_line(int argc, char** argv, const TablesExtension& tables_extension = {});

}  // namespace vsgl::cli
