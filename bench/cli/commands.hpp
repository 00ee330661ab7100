#pragma once
// The vsgl-bench subcommands. Each returns the process exit code (see harness/error.hpp).
#include "bench/cli/args.hpp"

namespace vsgl::cli {

int run_devices(Args& args);
int run_record(Args& args);
int run_tables(Args& args);
int run_verify(Args& args);
int run_shade(Args& args);

}  // namespace vsgl::cli
