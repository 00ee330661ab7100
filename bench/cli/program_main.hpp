#pragma once
// The one entry of every program (vsgl-bench, vsgl-gbench, vsgl-mipbench): names the program for
// messages, sets a UTF-8 console, passes the arguments as UTF-8 (file names beyond the ANSI code
// page on Windows; harness/core/platform_*) and maps what `body` throws to an exit code
// (exit_codes.hpp).
#include <functional>

namespace vsgl::cli {

int run_program(const char* name, int argc, char** argv, const std::function<int(int argc, char** argv)>& body);

}  // namespace vsgl::cli
