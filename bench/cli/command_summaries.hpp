#pragma once
// The one line `vsgl-bench --help` gives each command, as git and cargo list theirs. A command's
// own `vsgl-bench <command> --help` keeps its whole description (its add_*_command, commands.hpp).
#include <string_view>

#include <CLI/CLI.hpp>

namespace vsgl::cli {

// The one-line summary of `command`; empty for a name that has none.
std::string_view command_summary(std::string_view command);

// Makes the help of `app` (the top level) list its commands under "Commands:", one line each, from
// command_summary; a command without a summary is listed with its whole description. Call it once
// the commands are added. The commands' own help is
// unchanged: their formatter is the one they were created with.
void list_commands_in_one_line(CLI::App& app);

}  // namespace vsgl::cli
