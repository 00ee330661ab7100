#pragma once
// Both Google Benchmark front ends (vsgl-gbench, vsgl-mipbench) hand what CLI11 left to
// benchmark::Initialize the same way. Header-only: the CLI library does not link Google Benchmark.
#include <benchmark/benchmark.h>

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/cli/command_line.hpp"
#include "bench/cli/exit_codes.hpp"

namespace vsgl::cli {

// Initializes Google Benchmark with the --benchmark_* arguments CLI11 left (anything else is a
// UsageError from benchmark_arguments); an argument it does not recognise is a usage error too.
// Returns the exit code to stop with, or nullopt to go on. Google Benchmark copies the flag values,
// so the argument strings need not outlive the call.
inline std::optional<int> initialize_benchmark(const CLI::App& app, char* program) {
  std::vector<std::string> extras = benchmark_arguments(app);
  std::vector<char*> argv{program};
  for (std::string& a : extras) argv.push_back(a.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());
  if (benchmark::ReportUnrecognizedArguments(argc, argv.data())) return static_cast<int>(ExitCode::kUsage);
  return std::nullopt;
}

}  // namespace vsgl::cli
