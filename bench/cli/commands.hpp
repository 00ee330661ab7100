#pragma once
// The vsgl-bench subcommands. Each returns the process exit code (see harness/core/error.hpp).
#include <string>
#include <vector>

#include "bench/cli/args.hpp"

namespace vsgl::cli {

int run_devices(Args& args);
int run_record(Args& args);
int run_tables(Args& args);
int run_verify(Args& args);
int run_shade(Args& args);
int run_quality(Args& args);
// Commands with positional arguments take the raw tokens after the command name.
int run_compare(std::vector<std::string> tokens);
int run_export(std::vector<std::string> tokens);
int run_dashboard(std::vector<std::string> tokens);
// Removes the positional arguments from `tokens` and returns them; `value_options` are the
// options whose next token is their value (command_compare.cpp).
std::vector<std::string> take_positionals(std::vector<std::string>& tokens, const std::vector<std::string>& value_options);

}  // namespace vsgl::cli
