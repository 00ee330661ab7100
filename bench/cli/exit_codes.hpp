#pragma once
// The exit codes, documented once: this table generates the --help footer (README points to it),
// and one mapping from the harness's exceptions to the codes, shared by every front end, so that
// a Vulkan failure is a device problem (4) and an unexpected exception a bug (70) in all of them.
#include <functional>
#include <span>
#include <string>

#include "harness/core/error.hpp"

namespace vsgl::cli {

struct ExitCodeMeaning {
  ExitCode code;
  const char* meaning;
};

std::span<const ExitCodeMeaning> exit_code_table();
// "exit codes:\n  0  ok\n  1  ..." for the --help footer.
std::string exit_codes_help();

// Runs `body` and returns its exit code; an exception becomes a message on stderr, prefixed with
// program_name(), and its exit code: UsageError 2, InputError 3, DeviceError and VulkanError 4,
// any other std::exception 70 ("internal error: ...; please report it with the command line").
int run_reporting_errors(const std::function<int()>& body);

}  // namespace vsgl::cli
