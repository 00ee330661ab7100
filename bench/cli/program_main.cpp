#include "bench/cli/program_main.hpp"

#include "bench/cli/exit_codes.hpp"
#include "harness/core/platform_arguments.hpp"
#include "harness/core/platform_console.hpp"
#include "harness/core/program_name.hpp"

namespace vsgl::cli {

int run_program(const char* name, int argc, char** argv, const std::function<int(int argc, char** argv)>& body) {
  set_program_name(name);
  use_utf8_console();
  Utf8Arguments args(argc, argv);
  return run_reporting_errors([&] { return body(args.argc(), args.argv()); });
}

}  // namespace vsgl::cli
