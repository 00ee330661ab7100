#pragma once
// Parsing a whole command line with CLI11 before anything else runs (no Vulkan instance is
// opened before it is valid): --help and --version exit 0, a parse error exits 2 with CLI11's
// message on stderr.
#include <optional>
#include <string>
#include <vector>

// Only declarations name CLI11 here; the files that build options include <CLI/CLI.hpp>.
namespace CLI {
class App;
}  // namespace CLI

namespace vsgl::cli {

// Returns nothing to go on, else the exit code to return now.
std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv);

// The Google Benchmark front ends (allow_extras): the arguments CLI11 left, every one a
// --benchmark_* flag for benchmark::Initialize; anything else throws UsageError.
std::vector<std::string> benchmark_arguments(const CLI::App& app);

}  // namespace vsgl::cli
