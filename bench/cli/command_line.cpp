#include "bench/cli/command_line.hpp"

#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "harness/core/error.hpp"
#include "harness/core/program_name.hpp"

namespace vsgl::cli {

std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv) {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::ParseError& e) {
    // --help, --help-all, --version: CLI11 prints the help of the command it was asked of; 0.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::string command = program_name();  // "vsgl-bench quality": the help that lists the option
    for (const CLI::App* sub : app.get_subcommands()) command += " " + sub->get_name();
    std::fprintf(stderr, "%s: %s (see %s --help)\n", program_name().c_str(), e.what(), command.c_str());
    return static_cast<int>(ExitCode::kUsage);
  }
}

std::vector<std::string> benchmark_arguments(const CLI::App& app) {
  std::vector<std::string> out = app.remaining();
  for (const std::string& a : out)
    if (a.rfind("--benchmark_", 0) != 0)
      throw UsageError("unknown argument '" + a + "' (this tool's own options start with --vsgl_, Google "
                       "Benchmark's with --benchmark_)");
  return out;
}

}  // namespace vsgl::cli
