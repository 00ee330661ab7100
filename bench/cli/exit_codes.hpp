#pragma once
// One mapping from the harness's exceptions to the exit codes of --help (harness/core/error.hpp),
// shared by vsgl-bench and vsgl-gbench so that a Vulkan failure is a device problem (4) in both.
#include <functional>

namespace vsgl::cli {

// Runs `body` and returns its exit code; an exception becomes a message on stderr, prefixed with
// `program`, and its exit code.
int run_reporting_errors(const char* program, const std::function<int()>& body);

}  // namespace vsgl::cli
