// vsgl-bench: reproduce the timing tables of Tokuyoshi 2016 (Modified FIS for VSGLs) on any
// Vulkan device. Subcommands live in bench/cli/ and declare their own options (CLI11); this file
// parses the whole command line before any command runs (so a typo exits 2 without touching
// Vulkan) and maps errors to exit codes.
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/cli/command_line.hpp"
#include "bench/cli/command_summaries.hpp"
#include "bench/cli/commands.hpp"
#include "bench/cli/exit_codes.hpp"
#include "bench/cli/program_main.hpp"
#include "bench/cli/program_version.hpp"
#include "harness/core/error.hpp"

namespace {

int dispatch(int argc, char** argv) {
  CLI::App app("vsgl-bench: GPU timing of VSGL generators (Tokuyoshi 2016, Tables 1-3)", "vsgl-bench");
  // The version, the commit the build was made from (and whether it was dirty), the compiler and
  // the Vulkan headers, as fixed at build time: true wherever the binary was copied; the licence.
  app.set_version_flag("--version", vsgl::cli::program_version_text("vsgl-bench"));
  app.footer(vsgl::cli::exit_codes_help());  // inherited by every command's help
  // CLI11 takes "/name" for an option on Windows by default; here it is a path, as elsewhere.
  app.allow_windows_style_options(false);
  // A repeated single-value option keeps its last value, as before; list options say so.
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  const std::vector<vsgl::cli::Command> commands{
      vsgl::cli::add_devices_command(app),   vsgl::cli::add_record_command(app),  vsgl::cli::add_verify_command(app),
      vsgl::cli::add_shade_command(app),     vsgl::cli::add_quality_command(app), vsgl::cli::add_tables_command(app),
      vsgl::cli::add_sweep_command(app),     vsgl::cli::add_compare_command(app), vsgl::cli::add_export_command(app),
      vsgl::cli::add_dashboard_command(app),
  };
  vsgl::cli::list_commands_in_one_line(app);  // each command's own --help keeps its whole description
  app.footer("`vsgl-bench <command> --help` lists a command's options.\n\n" + vsgl::cli::exit_codes_help());
  if (argc == 2 && std::string(argv[1]) == "help") {  // `vsgl-bench help`, as before: the top-level help
    std::fputs(app.help().c_str(), stdout);
    return 0;
  }
  if (const auto exit_code = vsgl::cli::parse_command_line(app, argc, argv)) return *exit_code;
  for (const auto& c : commands)
    if (c.app->parsed()) return c.run();
  throw vsgl::UsageError(
      "a command is required: devices, record, verify, shade, quality, tables, sweep, compare, export "
      "or dashboard");
}

}  // namespace

int main(int argc, char** argv) { return vsgl::cli::run_program("vsgl-bench", argc, argv, dispatch); }
