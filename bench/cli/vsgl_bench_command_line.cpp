#include "bench/cli/vsgl_bench_command_line.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/cli/command_line.hpp"
#include "bench/cli/command_summaries.hpp"
#include "bench/cli/commands.hpp"
#include "bench/cli/exit_codes.hpp"
#include "bench/cli/program_version.hpp"
#include "harness/core/error.hpp"

namespace vsgl::cli {

int vsgl_bench_command_line(int argc, char** argv, const TablesExtension& tables_extension) {
  CLI::App app("vsgl-bench: GPU timing of VSGL generators (Tokuyoshi 2016, Tables 1-3)", "vsgl-bench");
  // The version, the commit the build was made from (and whether it was dirty), the compiler and
  // the Vulkan headers, as fixed at build time: true wherever the binary was copied; the licence.
  app.set_version_flag("--version", program_version_text("vsgl-bench"));
  app.footer(exit_codes_help());  // inherited by every command's help
  // CLI11 takes "/name" for an option on Windows by default; here it is a path, as elsewhere.
  app.allow_windows_style_options(false);
  // A repeated single-value option keeps its last value, as before; list options say so.
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  const std::vector<Command> commands{
      add_devices_command(app), add_record_command(app),    add_verify_command(app),
      add_shade_command(app),   add_quality_command(app),   add_tables_command(app, tables_extension),
      add_frame_command(app),   add_sweep_command(app),     add_compare_command(app),
      add_export_command(app),  add_dashboard_command(app),
  };
  list_commands_in_one_line(app);  // each command's own --help keeps its whole description
  app.footer("`vsgl-bench <command> --help` lists a command's options.\n\n" + exit_codes_help());
  if (argc == 2 && std::string(argv[1]) == "help") {  // `vsgl-bench help`, as before: the top-level help
    std::fputs(app.help().c_str(), stdout);
    return 0;
  }
  if (const auto exit_code = parse_command_line(app, argc, argv)) return *exit_code;
  for (const auto& c : commands)
    if (c.app->parsed()) return c.run();
  throw UsageError(
      "a command is required: devices, record, verify, shade, quality, tables, frame, sweep, compare, "
      "export or dashboard");
}

}  // namespace vsgl::cli
