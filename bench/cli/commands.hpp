#pragma once
// The vsgl-bench subcommands. Each add_*_command declares its subcommand, its description and its
// options on `parent` (CLI11) and returns the run that uses them once the whole command line has
// been parsed; a run returns the process exit code (bench/cli/exit_codes.hpp).
#include <functional>

#include <CLI/CLI.hpp>

#include "bench/cli/tables_extension.hpp"

namespace vsgl::cli {

struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

Command add_devices_command(CLI::App& parent);
Command add_record_command(CLI::App& parent);
Command add_tables_command(CLI::App& parent, const TablesExtension& extension = {});
Command add_frame_command(CLI::App& parent);
Command add_sweep_command(CLI::App& parent);
Command add_verify_command(CLI::App& parent);
Command add_shade_command(CLI::App& parent);
Command add_quality_command(CLI::App& parent);
Command add_compare_command(CLI::App& parent);
Command add_export_command(CLI::App& parent);
Command add_dashboard_command(CLI::App& parent);

}  // namespace vsgl::cli
